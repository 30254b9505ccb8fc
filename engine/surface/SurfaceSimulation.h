#pragma once
/// @file SurfaceSimulation.h
/// A surface scene advancing frame by frame on the CPU (README.md, "Curved surfaces"): the modal
/// velocity with the same integrators, viscosity and LANS-α as a grid scene's, and the dye it
/// carries (SurfaceDye). `run` writes its frames (engine/output/PlyFrame.h).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/surface/SurfaceDye.h"

namespace modeflow {

class SurfaceSimulation {
public:
    /// Keeps references to `cache`, `coefficients` and `settings`, which must outlive it.
    /// @throw modeflow::Error as SurfaceDye does, or for settings FluidSystem refuses.
    SurfaceSimulation(const BasisCache& cache, const StructuralCoefficients& coefficients,
                      const SimulationSettings& settings, const Eigen::VectorXd& velocity);

    /// settings.stepsPerFrame steps.
    /// @throw ModalStateDiverged when a step leaves the modal state non-finite.
    void advanceFrame();
    /// Continues from a saved state (a resumed run).
    /// @throw modeflow::Error on wrong sizes.
    void restore(double time, const Eigen::VectorXd& velocity, const Eigen::VectorXd& dye);

    double time() const { return mTime; }
    const Eigen::VectorXd& velocity() const { return mVelocity; }
    const SurfaceDye& dye() const { return mDye; }
    /// The velocity at the vertices, x, y, z per vertex.
    std::vector<double> vertexVelocity() const;

private:
    const BasisCache& mCache;
    const SimulationSettings& mSettings;
    FluidSystem mSystem;
    ModalIntegrator mIntegrator;
    SurfaceDye mDye;
    Eigen::VectorXd mVelocity;
    double mTime = 0.0;
    long mStep = 0;
};

}  // namespace modeflow
