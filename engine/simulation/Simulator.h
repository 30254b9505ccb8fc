#pragma once
/// @file Simulator.h
/// One scene advancing frame by frame: modal velocity (and, with MHD, magnetic field), forces
/// from the smoke, and the smoke it carries. Two implementations run the same model:
/// device::Simulation on a Vulkan device (float32) and reference::Simulation on the CPU
/// (double), so any run can be made on both and compared (`--device cpu`); `run`, `stir` and the
/// tests drive them through this interface alone.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/simulation/ForceSplat.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/Particles.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/simulation/SmokeFields.h"
#include "engine/simulation/StepCarry.h"

namespace modeflow {

class Simulator {
public:
    virtual ~Simulator() = default;

    /// The modal velocity v (N values).
    /// @throw modeflow::Error on a wrong size.
    virtual void setVelocity(const Eigen::VectorXd& v) = 0;
    virtual Eigen::VectorXd velocity() const = 0;
    /// Continues from a saved state (a resumed run): the time, the modal velocity and the smoke;
    /// no particles until setParticles().
    /// @throw modeflow::Error on wrong sizes.
    virtual void restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) = 0;
    /// What the simulator carries from one step to the next beyond its state (StepCarry.h);
    /// nothing after setVelocity or restore. A checkpoint saves it and a resumed run sets it
    /// after restore(), so that it continues bit for bit.
    virtual StepCarry carry() const = 0;
    /// @throw modeflow::Error on wrong sizes, non-finite values, a rate or warm start the scheme
    /// holds none of, or a substep schedule the backend does not take.
    virtual void setCarry(const StepCarry& carry) = 0;
    /// MHD (seed §6.3.5): the modal magnetic field F (N values in the velocity basis); empty
    /// when the run simulates none. The defaults are those of a runtime without MHD.
    virtual Eigen::VectorXd magneticField() const { return {}; }
    /// @throw modeflow::Error on a wrong size, or when the run simulates no magnetic field.
    virtual void setMagneticField(const Eigen::VectorXd&) {
        throw Error("simulation: this run simulates no magnetic field ([simulation].mhd)");
    }
    /// The `[[particles]]` now, in emission order (Particles.h); none without sets.
    virtual Particles particles() const = 0;
    /// Continues from saved particles (a resumed run), after restore(): those the sets emitted
    /// until then, as particles() gave them.
    /// @throw modeflow::Error when they do not fit the scene's sets (ParticleEmission::restore)
    ///        or hold a non-finite value.
    virtual void setParticles(const Particles& particles) = 0;
    /// Stirring splats acting from the next step on (replacing earlier ones).
    virtual void setSplats(std::span<const ForceSplat> splats) = 0;

    /// Interactive changes (`modeflow stir`), between steps: the moving obstacles of the
    /// following steps, the viscosity ν, and the integrator.
    /// @throw modeflow::Error for more than maxObstacles or a negative ν.
    virtual void setObstacles(std::vector<MovingObstacle> obstacles) = 0;
    /// The smoke sources of the following steps, in place of the scene's (the Python module's
    /// moving sources).
    /// @throw modeflow::Error for more than maxSmokeEmitters.
    virtual void setEmitters(std::vector<SmokeEmitter> emitters) = 0;
    virtual void setViscosity(double viscosity) = 0;
    virtual void setIntegrator(Integrator integrator) = 0;

    /// `steps` steps, each: forces from the current smoke, the modal step, the grid velocity,
    /// moving obstacles, smoke advection and emitters, smoke out of solids, particles.
    /// @throw ModalStateDiverged (engine/dynamics/ModalDivergence.h) when a step leaves the modal
    /// state non-finite.
    virtual FrameStats advanceSteps(int steps) = 0;
    /// settings().stepsPerFrame steps.
    FrameStats advanceFrame() { return advanceSteps(settings().stepsPerFrame); }
    /// Whether the following steps time their stages (FrameStats), where the backend can
    /// (BackendCapabilities::stageTimes); timing may cost as much as the step on some devices.
    virtual void setTiming(bool) {}

    /// The smoke now (one value per cell of smokeGrid()).
    virtual SmokeFields smoke() const = 0;
    /// The velocity now as a face field of the basis grid (MacGrid.h).
    virtual std::vector<double> faceVelocity() const = 0;
    /// The magnetic field now as a face field of the basis grid, reconstructed from F as
    /// faceVelocity() is from v; empty without MHD.
    virtual std::vector<double> faceMagneticField() const { return {}; }

    virtual const SimulationSettings& settings() const = 0;
    virtual const MacGrid& smokeGrid() const = 0;
    /// Simulated time since the start.
    virtual double time() const = 0;
};

}  // namespace modeflow
