#include "engine/device/SurfaceSimulation.h"

#include <algorithm>
#include <cmath>

#include "engine/core/Error.h"
#include "engine/dynamics/ModalDivergence.h"

namespace modeflow::device {

SurfaceSimulation::SurfaceSimulation(const vulkan::VulkanContext& context, const BasisCache& cache,
                                     const StructuralCoefficients& coefficients,
                                     const SimulationSettings& settings,
                                     const Eigen::VectorXd& velocity, StepRecording recording)
    : mContext(context),
      mCache(cache),
      mSettings(settings),
      mStepper(context, coefficients, modelOf(settings), DeviceStepSettings{settings.integrator}),
      mDye(context, cache, settings.emitters),
      mBefore(context, std::size_t(std::max(mStepper.size(), 1)) * sizeof(float),
              "velocity before the step"),
      mRecording(recording),
      mStepSequence(context),
      mSequence(context) {
    if (!(mSettings.dt > 0.0)) throw Error("simulation: dt must be positive");
    mStepper.setVelocity(velocity);
    setSplats({});
}

void SurfaceSimulation::setSplats(std::span<const ForceSplat> splats) {
    if (splats.empty()) {
        mSequence.fill(mStepper.forceBuffer(), VkDeviceSize(mStepper.size()) * sizeof(float), 0);
    } else {
        if (!mForce) mForce.emplace(mContext, mCache);
        mForce->record(mSequence, splats, mStepper.forceBuffer());
    }
    mSequence.submitAndWait();
}

FrameStats SurfaceSimulation::advanceSteps(int steps) {
    FrameStats stats;
    const auto velocityBytes = VkDeviceSize(mStepper.size()) * sizeof(float);
    for (int s = 0; s < steps; ++s) {
        mDye.setRate(mTime);
        if (mStepSequence.hasKeptRecording() && mRecordedSubsteps == mSchedule.substeps()) {
            mStepSequence.resubmit();
        } else {
            if (mRecording == StepRecording::Once) mStepSequence.keepNextRecording();
            if (velocityBytes > 0)
                mStepSequence.copy(mStepper.stateBuffer(), mBefore, velocityBytes);
            mStepper.recordStep(mStepSequence, mSettings.dt, mSchedule.substeps());
            mDye.recordStep(mStepSequence, mBefore, mStepper.stateBuffer(), mSettings.dt);
            mStepSequence.submitAndWait();
            mRecordedSubsteps = mSchedule.substeps();
        }
        mTime += mSettings.dt;
        ++stats.steps;
        requireFiniteModalState(mStepper.state(), ++mStep, mTime);
        const DeviceStepStatus status = mStepper.status();
        stats.maxIterations = std::max(stats.maxIterations, status.iterations);
        stats.unconvergedSteps += mSchedule.advance(status);
        // A dye solve that met no tolerance in its budget keeps its last iterate: counted too.
        if (!mDye.status().converged) ++stats.unconvergedSteps;
        stats.substeps = std::max(stats.substeps, mSchedule.substeps());
    }
    return stats;
}

void SurfaceSimulation::restore(double time, const Eigen::VectorXd& velocity,
                                const Eigen::VectorXd& dye) {
    mDye.setState(dye);
    mStepper.setVelocity(velocity);
    mTime = time;
    mStep = std::lround(time / mSettings.dt);
    mSchedule.reset();
}

StepCarry SurfaceSimulation::carry() const {
    return carryOf(mStepper, mSchedule);
}

void SurfaceSimulation::setCarry(const StepCarry& carry) {
    restoreCarry(carry, mStepper, mSchedule);
}

void SurfaceSimulation::setViscosity(double viscosity) {
    SimulationSettings changed = mSettings;
    changed.fluid.viscosity = viscosity;
    mStepper.setParameters(modelOf(changed));
    mSettings = changed;
    mStepSequence.dropKeptRecording();  // the mass may change what a step records
}

void SurfaceSimulation::setIntegrator(Integrator integrator) {
    mStepper.setIntegrator(integrator);
    mSettings.integrator = integrator;
    mStepSequence.dropKeptRecording();
}

}  // namespace modeflow::device
