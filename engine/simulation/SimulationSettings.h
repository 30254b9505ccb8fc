#pragma once
/// @file SimulationSettings.h
/// Everything a simulation of one scene needs besides its basis (engine/README.md): the step, the
/// fluid's parameters, forces and smoke. Built from a scene and its basis, so the device
/// device::Simulation and the CPU reference::Simulation of one scene run the same model.

#include <optional>
#include <vector>

#include "engine/core/ModePrecision.h"
#include "engine/core/SceneSpec.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/FrameStats.h"
#include "engine/simulation/InflowPatch.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/SmokeEmitter.h"

namespace modeflow {

struct SimulationSettings {
    double dt = 0.02;
    int stepsPerFrame = 1;
    Integrator integrator = Integrator::Midpoint;
    FluidParameters fluid;  ///< κ² of the basis, viscosity ν, LANS-α
    /// MHD (seed §6.3.5): a magnetic field F in the velocity basis, advected
    /// by the flow and acting back on it, decaying at the magnetic diffusivity η.
    bool mhd = false;
    double magneticDiffusivity = 0.0;
    double buoyancy = 0.0;  ///< upward acceleration per unit temperature
    int smokeScale = 1;     ///< smoke cells per basis cell and axis
    AdvectionScheme advection = AdvectionScheme::MacCormack;
    std::optional<FireSpec> fire;  ///< `[fire]`: fuel and flame are carried (Combustion.h)
    /// `[wind]`: the base flow U under the modes (WindTransport.h): a simulation makes its
    /// advection of the modes fluid.linear over its basis; grid velocities and smoke see U + Ψ v,
    /// the smoke arriving clean upstream.
    std::optional<WindSpec> wind;
    ModePrecision basisPrecision = ModePrecision::Float32;  ///< device only
    std::vector<SmokeEmitter> emitters;
    /// `[[inflow]]` patches: what the air coming in through them carries (OutsideAir.h), and
    /// their regions driving it where they have a velocity.
    std::vector<InflowPatch> inflows;
    std::vector<MovingObstacle> obstacles;
    /// `[[particles]]` sets (ParticleEmission.h, ParticleMotion.h), emitting until shotEnd at most:
    /// frames × steps per frame × dt.
    std::vector<ParticleSetSpec> particles;
    double shotEnd = 0.0;

    /// What the velocity correction holds during the step starting at t (seed §6.3.5): the
    /// obstacles, then the sources and inflows with a `velocity` active at t, as regions of their
    /// shape whose material moves at that velocity (MovingObstacle::drive). The first region
    /// covering a face sets its velocity, so a solid wins over a jet.
    std::vector<MovingObstacle> velocityRegions(double t) const;

    /// Whether the run simulates temperature: a source heats, buoyancy reads it, or a fire burns.
    /// Frames then carry a temperature grid and pictures tint hot smoke.
    bool simulatesTemperature() const;

    /// The scene's [simulation], [smoke], [[source]], [wind] and [output] values on this basis
    /// (both backends run every one they take, BackendCapabilities.h).
    /// @throw modeflow::Error for more emitters or obstacles than the runtime takes.
    static SimulationSettings fromScene(const SceneSpec& scene, const BasisCache& cache);
};

/// The 0-based modes `[forcing]` holds: the positions of hold_modes, or the modes with κ below
/// hold_below_kappa (κ² < hold_below_kappa², harmonic ones included).
/// @throw modeflow::Error naming the key when it holds no mode, or every mode, of the basis.
std::vector<int> heldModes(const SceneSpec& scene, const BasisCache& cache);

}  // namespace modeflow
