#pragma once
/// @file Simulation.h
/// One scene on a Vulkan device (issue 4's runtime): the modal state, the velocity basis, the
/// grid velocity and the smoke all live in device buffers, and each step is one queue submission
///
///     force field (buoyancy from the smoke temperature + stirring splats) → projection f = Ψᵀ⋆F
///     → modal step (viscosity, LANS-α; a wind's D v) → reconstruction u = Σ v_i Ψ_i
///     (the basis's columns, or a closed-form basis's separable transforms) + the wind U
///     → moving obstacles (v −= projected mismatch, reconstruct again) → smoke advection + emitters
///     → smoke pushed out of solids → fuel burning ([fire]) → particles
///
/// with nothing read back; the host reads the velocity, smoke or grid velocity only when it asks
/// (display, export). CPU reference of the whole chain: reference::Simulation.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/device/ConservativeTransport.h"
#include "engine/device/FireBurn.h"
#include "engine/device/ForceField.h"
#include "engine/device/ForceProjection.h"
#include "engine/device/ModalStepper.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/ObstacleCorrection.h"
#include "engine/device/ParticleAdvection.h"
#include "engine/device/SeparableTransform.h"
#include "engine/device/SmokeAdvection.h"
#include "engine/device/SmokeDisplacement.h"
#include "engine/device/SmokeState.h"
#include "engine/device/StepRecording.h"
#include "engine/device/SubstepSchedule.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/device/WindField.h"
#include "engine/simulation/InflowPatch.h"
#include "engine/simulation/Simulator.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::device {

class Simulation final : public Simulator {
public:
    /// Uploads the basis and coefficients. `smokeMask`: one byte per cell of the smoke grid
    /// (basis grid refined by settings.smokeScale), non-zero inside Ω (precompute's fluidMask).
    /// `timestamps`: time each stage on the device (FrameStats), where the queue can.
    /// `recording`: a step whose commands stay the same (no solids, particles or conservative
    /// smoke; its open sides letting in air unchanged, and jets within the box its recording
    /// walks) is recorded once and resubmitted.
    /// @throw modeflow::Error for LANS-α with MHD, a mask of the wrong size, or a device error.
    Simulation(const vulkan::VulkanContext& context, const BasisCache& cache,
               const StructuralCoefficients& coefficients, SimulationSettings settings,
               std::span<const std::uint8_t> smokeMask, bool timestamps = false,
               StepRecording recording = StepRecording::Once);

    void setVelocity(const Eigen::VectorXd& v) override { mStepper.setVelocity(v); }
    Eigen::VectorXd velocity() const override { return mStepper.velocity(); }
    StepCarry carry() const override;
    void setCarry(const StepCarry& carry) override;
    Eigen::VectorXd magneticField() const override;
    void setMagneticField(const Eigen::VectorXd& f) override { mStepper.setMagneticField(f); }
    std::vector<double> faceMagneticField() const override;
    void restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) override;
    Particles particles() const override { return mParticles.particles(); }
    void setParticles(const Particles& particles) override { mParticles.restore(particles); }
    void setSplats(std::span<const ForceSplat> splats) override;
    /// Each step is its own submission.
    FrameStats advanceSteps(int steps) override;
    SmokeFields smoke() const override;
    std::vector<double> faceVelocity() const override;
    const SimulationSettings& settings() const override { return mSettings; }
    const MacGrid& smokeGrid() const override { return mSmoke.smokeGrid(); }
    double time() const override { return mTime; }

    void setObstacles(std::vector<MovingObstacle> obstacles) override;
    void setEmitters(std::vector<SmokeEmitter> emitters) override;
    void setViscosity(double viscosity) override;
    void setIntegrator(Integrator integrator) override;
    /// Timestamps (constructed with `timestamps`; on by default then) cost lavapipe about as much
    /// as the step itself, so a window showing times a few times a second times a sample
    /// (FrameStats::timedSteps).
    void setTiming(bool on) override;
    /// The smoke and the grid velocity on the device, for kernels that draw them (valid between
    /// frames; the velocity is a face field of the basis grid).
    const SmokeState& smokeState() const { return mSmoke; }
    const vulkan::DeviceBuffer& faceVelocityBuffer() const { return mFaceVelocity; }

private:
    /// What a step records besides its buffers' contents (which are uploaded before each
    /// submission): a kept step runs again for a step of the same shape whose regions lie in
    /// its regions' box.
    struct StepShape {
        int substeps = 0;
        std::uint32_t inflowBits = 0;  ///< the open sides letting air in (the advection's)
        std::uint32_t regionCount = 0, regionKinds = 0;
        std::uint64_t latticeGeneration = 0;
        CellBox regionBox;  ///< the cells the regions' correction walks
    };

    /// A step recorded once and resubmitted while what it records stays the same, for one parity
    /// of the smoke's fields (the advection swaps them each step).
    struct KeptStep {
        KeptStep(const vulkan::VulkanContext& context, bool timestamps, std::uint32_t dispatches)
            : sequence(context, timestamps, dispatches) {}
        vulkan::CommandSequence sequence;
        std::vector<std::size_t> boundaries;  ///< its stages' dispatch ranges
        StepShape shape;
        int endParity = 0;  ///< the smoke's parity after it
    };

    /// Steps whose regions' box a kept step's recording covers: it walks the faces of where
    /// the regions are over this many steps, and is recorded again when they leave it.
    static constexpr int kSweptSteps = 8;

    /// Uploads the emitters and inflows of the step from mTime where they changed, and the
    /// step's velocity regions (mRegions) where they are at its end; whether the step may run as
    /// a kept one (no solids, particles or conservative smoke: those record afresh).
    bool prepareStep();
    /// The shape of the step prepareStep() prepared.
    StepShape stepShape() const;
    /// Whether `kept` recorded a step of this shape.
    bool recordedFor(const StepShape& kept, const StepShape& shape) const;
    /// Forgets the kept steps (what a step records changed).
    void dropKeptSteps();
    /// Where a step records now.
    vulkan::CommandSequence& recording() const { return *mRecordingInto; }
    /// Records one whole step into recording(); adds each stage's dispatch range to `ranges`.
    void recordStep(std::vector<std::size_t>& boundaries);
    /// Dispatches of the step so far, in the submissions made and the one being recorded.
    std::size_t dispatchMark() const;
    /// Submits what is recorded and waits, keeping its dispatch times for the step's stats.
    void submitWithinStep();
    /// The grid velocity of the modal state; `needed`: at least on the faces of those cells.
    void recordReconstruction(const CellBox* needed = nullptr);
    /// The face field of the modal vector `modal` (v, or MHD's F) into `field` (`needed` as
    /// above).
    void recordReconstruction(const vulkan::DeviceBuffer& modal, const vulkan::DeviceBuffer& field,
                              const CellBox* needed = nullptr) const;
    bool forcesActive() const { return mSettings.buoyancy != 0.0 || mForceField.splatCount() > 0; }

    SimulationSettings mSettings;
    /// The basis: its columns (an eigensolved basis), or the transforms of a closed-form one,
    /// whose columns are never formed.
    std::unique_ptr<ModeBuffer> mModes;
    std::unique_ptr<SeparableTransformKernels> mSeparable;
    ModalStepper mStepper;
    ReconstructionKernel mReconstruction;
    vulkan::DeviceBuffer mFaceVelocity;
    ForceFieldKernel mForceField;
    ForceProjectionKernel mProjection;
    vulkan::DeviceBuffer mForceDensity;
    ObstacleCorrection mObstacles;
    SmokeState mSmoke;
    SmokeAdvectionKernels mAdvection;
    std::optional<ConservativeTransport> mFlux;  ///< with [smoke] advection = "conservative"
    SmokeDisplacement mDisplacement;
    ParticleAdvection mParticles;
    std::optional<FireBurnKernel> mBurn;  ///< with [fire]
    std::optional<WindField> mWind;       ///< with [wind]: U added to each reconstruction
    mutable vulkan::CommandSequence
        mSequence;  ///< steps recorded afresh; also faceMagneticField()'s reconstruction
    StepRecording mStepRecording;
    std::array<std::unique_ptr<KeptStep>, 2> mKept;        ///< by the smoke's parity
    vulkan::CommandSequence* mRecordingInto = &mSequence;  ///< where recordStep() records
    std::vector<MovingObstacle> mRegions;  ///< the step's obstacles and jets (prepareStep)
    std::vector<bool> mActiveEmitters;     ///< what the device's emitter list holds now
    ActiveInflowSet mActiveInflows;        ///< the inflows the device's ghosts hold now
    std::size_t mStepDispatches = 0;       ///< dispatches of the step's earlier submissions
    std::vector<double> mStepTimesMs;      ///< their times, and the last submission's
    std::vector<std::string> mStepLabels;  ///< what each timed one was
    SubstepSchedule mSchedule;
    double mTime = 0.0;
    long mStep = 0;  ///< steps since t = 0, for the divergence message
};

}  // namespace modeflow::device
