#pragma once
/// @file SurfaceSimulation.h
/// A surface scene on a Vulkan device (SurfaceSimulator.h), in float32: the modal velocity
/// advanced by the grids' ModalStepper (every integrator, viscosity, LANS-α; its substeps
/// scheduled as for grids, SubstepSchedule.h), stirred by splats (device::SurfaceForce), and the
/// dye it carries (device::SurfaceDye), one submission a step. A step is recorded once and
/// resubmitted (CommandSequence::keepNextRecording) until its substeps, integrator or parameters
/// change; the sources' rate, the one thing that changes from step to step, is a buffer. A step
/// whose dye solve met no tolerance within its budget counts as unconverged (FrameStats). CPU
/// reference: engine/surface/SurfaceSimulation.h.

#include <optional>

#include <Eigen/Core>

#include "engine/device/ModalStepper.h"
#include "engine/device/StepRecording.h"
#include "engine/device/SubstepSchedule.h"
#include "engine/device/SurfaceDye.h"
#include "engine/device/SurfaceForce.h"
#include "engine/simulation/SurfaceSimulator.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::device {

class SurfaceSimulation final : public SurfaceSimulator {
public:
    /// Uploads the coefficients and the dye's; `context` and `cache` must outlive the simulation.
    /// @throw modeflow::Error for settings the model refuses, as SurfaceDye, or a device error.
    SurfaceSimulation(const vulkan::VulkanContext& context, const BasisCache& cache,
                      const StructuralCoefficients& coefficients,
                      const SimulationSettings& settings, const Eigen::VectorXd& velocity,
                      StepRecording recording = StepRecording::Once);

    FrameStats advanceSteps(int steps) override;
    void restore(double time, const Eigen::VectorXd& velocity, const Eigen::VectorXd& dye) override;
    StepCarry carry() const override;
    void setCarry(const StepCarry& carry) override;

    void setSplats(std::span<const ForceSplat> splats) override;
    void setViscosity(double viscosity) override;
    void setIntegrator(Integrator integrator) override;

    double time() const override { return mTime; }
    Eigen::VectorXd velocity() const override { return mStepper.velocity(); }
    Eigen::VectorXd dye() const override { return mDye.state(); }

    /// The last step's dye solve (tests).
    SurfaceDyeStatus dyeStatus() const { return mDye.status(); }

private:
    const vulkan::VulkanContext& mContext;
    const BasisCache& mCache;
    SimulationSettings mSettings;  ///< with the user's viscosity and integrator
    ModalStepper mStepper;
    SurfaceDye mDye;
    /// Made by the first splats (`stir`): a run never holds the modes' vertex velocities.
    std::optional<SurfaceForce> mForce;
    vulkan::DeviceBuffer mBefore;  ///< the velocity at the start of the step
    StepRecording mRecording;
    vulkan::CommandSequence mStepSequence;  ///< a step, kept (StepRecording::Once)
    int mRecordedSubsteps = 0;              ///< the substeps of the kept step
    vulkan::CommandSequence mSequence;      ///< the splats' force
    SubstepSchedule mSchedule;
    double mTime = 0.0;
    long mStep = 0;  ///< steps since t = 0, for the divergence message
};

}  // namespace modeflow::device
