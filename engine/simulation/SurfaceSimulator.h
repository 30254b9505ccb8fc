#pragma once
/// @file SurfaceSimulator.h
/// A surface scene advancing step by step (scenes/README.md, "Curved surfaces"): the modal
/// velocity with the same integrators, viscosity and LANS-α as a grid scene's, a modal force
/// (stirring) held over the following steps, and the dye it carries in the surface's scalar
/// basis. Two implementations run the same model, as Simulator's do for grids: SurfaceSimulation
/// on the CPU reference (double) and device::SurfaceSimulation on a Vulkan device (float32);
/// `run`, `stir` and the tests drive them through this interface alone.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "engine/simulation/ForceSplat.h"
#include "engine/simulation/FrameStats.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/simulation/StepCarry.h"

namespace modeflow {

class SurfaceSimulator {
public:
    virtual ~SurfaceSimulator() = default;

    /// `steps` steps of the settings' dt.
    /// @throw ModalStateDiverged when a step leaves the modal state non-finite.
    virtual FrameStats advanceSteps(int steps) = 0;
    /// Continues from a saved state (a resumed run): the time, the modal velocity and the dye's
    /// modal state [mean, f_1, …, f_M]; nothing carried until setCarry().
    /// @throw modeflow::Error on wrong sizes.
    virtual void restore(double time, const Eigen::VectorXd& velocity,
                         const Eigen::VectorXd& dye) = 0;
    /// What the steps carry (StepCarry.h), and its restore after restore().
    virtual StepCarry carry() const = 0;
    virtual void setCarry(const StepCarry& carry) = 0;

    /// The stirring splats of the following steps (none: no force), each turned into the
    /// surface's tangent planes and projected on the velocity basis (SurfaceForce.h).
    /// @throw modeflow::Error for more than maxForceSplats splats or a radius that is not
    ///        positive.
    virtual void setSplats(std::span<const ForceSplat> splats) = 0;
    /// Interactive changes between steps (`stir`). @throw modeflow::Error for a negative ν.
    virtual void setViscosity(double viscosity) = 0;
    virtual void setIntegrator(Integrator integrator) = 0;

    virtual double time() const = 0;
    virtual Eigen::VectorXd velocity() const = 0;
    /// The dye's modal state [mean, f_1, …, f_M]: what a checkpoint keeps.
    virtual Eigen::VectorXd dye() const = 0;
};

/// The dye at each vertex of `cache`'s surface from its modal state [mean, f_1, …, f_M].
std::vector<double> surfaceDyeAtVertices(const BasisCache& cache, const Eigen::VectorXd& dye);
/// The velocity at each vertex (x, y, z per vertex) of the modal velocity `velocity`.
std::vector<double> surfaceVelocityAtVertices(const BasisCache& cache,
                                              const Eigen::VectorXd& velocity);

/// The dye shown in full colour: four frames' worth of the strongest source's rate (1 without
/// sources), one scale for a whole run so that its pictures compare.
double dyeColourScale(const SimulationSettings& settings);

}  // namespace modeflow
