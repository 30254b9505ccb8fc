#pragma once
/// @file SurfaceSimulation.h
/// A surface scene advancing step by step on the CPU (scenes/README.md, "Curved surfaces"): the
/// modal velocity with the same integrators, viscosity and LANS-α as a grid scene's (the CPU
/// reference's modal stage, reference::ModalStepper), a modal force (stirring, SurfaceForce.h)
/// held over the following steps, and the dye it carries (SurfaceDye). `run` writes its frames
/// (engine/output/PlyFrame.h); `stir` stirs it.

#include <vector>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "engine/reference/ModalStepper.h"
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
    void advanceFrame() { advanceSteps(mSettings.stepsPerFrame); }
    /// `steps` steps of settings.dt. @throw ModalStateDiverged as advanceFrame().
    void advanceSteps(int steps);
    /// Continues from a saved state (a resumed run).
    /// @throw modeflow::Error on wrong sizes.
    void restore(double time, const Eigen::VectorXd& velocity, const Eigen::VectorXd& dye);

    /// The modal force of the following steps (N values; zero: none).
    /// @throw modeflow::Error on a wrong size.
    void setForce(const Eigen::VectorXd& force) { mStepper.setForce(force); }
    /// Interactive changes between steps (`stir`). @throw modeflow::Error for a negative ν.
    void setViscosity(double viscosity) { mStepper.setViscosity(viscosity); }
    void setIntegrator(Integrator integrator) { mStepper.setIntegrator(integrator); }

    double time() const { return mTime; }
    Eigen::VectorXd velocity() const { return mStepper.velocity(); }
    /// What the steps carry (Simulator::carry), and its restore after restore().
    StepCarry carry() const { return mStepper.carry(); }
    void setCarry(const StepCarry& carry) { mStepper.setCarry(carry); }
    const SurfaceDye& dye() const { return mDye; }
    /// The velocity at the vertices, x, y, z per vertex.
    std::vector<double> vertexVelocity() const;

private:
    const BasisCache& mCache;
    const SimulationSettings& mSettings;
    reference::ModalStepper mStepper;
    SurfaceDye mDye;
    double mTime = 0.0;
    long mStep = 0;
};

}  // namespace modeflow
