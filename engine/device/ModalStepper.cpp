#include "engine/device/ModalStepper.h"

#include <array>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/vulkan/CommandSequence.h"
#include "shaders/ModalStepParams.h"

namespace modeflow::device {
namespace {

DeviceStepSettings checked(DeviceStepSettings settings) {
    if (settings.scheme == Integrator::Trapezoidal)
        throw Error(
            "the trapezoidal integrator runs on the CPU reference only (--device cpu); the device "
            "offers explicit, rk4 and midpoint");
    if (!(settings.tolerance > 0.0f)) throw Error("device midpoint tolerance must be positive");
    if (settings.maxIterations < 1) throw Error("device midpoint iterations must be at least 1");
    return settings;
}

/// A zero modal vector, padded as the pair-sum kernel reads it.
vulkan::DeviceBuffer floats(const vulkan::VulkanContext& context, int n, const char* name) {
    return vulkan::DeviceBuffer::fromValues<float>(context, std::vector<float>(paddedSize(n), 0.0f), name);
}

vulkan::DeviceBuffer floats(const vulkan::VulkanContext& context, const Eigen::VectorXd& values, const char* name) {
    return vulkan::DeviceBuffer::fromValues<float>(context,
                                           std::vector<float>(values.begin(), values.end()), name);
}

/// The full indirect arguments (one VkDispatchIndirectCommand per dispatch of an iteration),
/// followed by the live copy the device resets and zeroes.
std::vector<std::uint32_t> indirectArguments(const std::vector<std::uint32_t>& groups) {
    std::vector<std::uint32_t> words;
    for (int copy = 0; copy < 2; ++copy)
        for (std::uint32_t g : groups) words.insert(words.end(), {g, 1u, 1u});
    return words;
}

std::vector<std::uint32_t> iterationGroups(const DeviceCoefficients& coefficients) {
    std::vector<std::uint32_t> groups = coefficients.dispatchGroups();
    groups.push_back(1);  // modal_update
    return groups;
}

}  // namespace

ModalStepper::ModalStepper(const vulkan::VulkanContext& context, const StructuralCoefficients& coefficients,
                           const FluidParameters& parameters, DeviceStepSettings settings)
    : mContext(context),
      mSettings(checked(settings)),
      mKernels(context),
      mCoefficients(context, coefficients),
      mApplyDispatches(std::uint32_t(mCoefficients.dispatchGroups().size())),
      mState(floats(context, coefficients.size(), "modal state")),
      mPoint(floats(context, coefficients.size(), "modal evaluation point")),
      mWeighted(floats(context, coefficients.size(), "modal weighted point")),
      mRhs(floats(context, coefficients.size(), "modal right-hand side")),
      mForce(floats(context, coefficients.size(), "modal force")),
      mMass(floats(context, FluidSystem::massOf(parameters, coefficients.size()), "modal mass")),
      mDecay(floats(context, FluidSystem::decayRatesOf(parameters, coefficients.size()),
                    "modal decay rates")),
      mAccumulator(floats(context, coefficients.size(), "modal RK4 accumulator")),
      mStatus(vulkan::DeviceBuffer::fromValues<shaders::ModalStatus>(
          context, std::vector<shaders::ModalStatus>(1), "modal status")),
      mArguments(vulkan::DeviceBuffer::fromValues<std::uint32_t>(
          context, indirectArguments(iterationGroups(mCoefficients)), "modal indirect arguments")) {
}

void ModalStepper::upload(vulkan::DeviceBuffer& buffer, const Eigen::VectorXd& values,
                          const char* what) const {
    if (values.size() != size())
        throw Error(std::string("modal ") + what + " has " + std::to_string(values.size()) +
                    " entries, the basis " + std::to_string(size()));
    const std::vector<float> rounded(values.begin(), values.end());
    buffer.upload<float>(rounded);
}

void ModalStepper::setScheme(Integrator scheme) {
    DeviceStepSettings settings = mSettings;
    settings.scheme = scheme;
    mSettings = checked(settings);
}

void ModalStepper::setParameters(const FluidParameters& parameters) {
    upload(mMass, FluidSystem::massOf(parameters, size()), "mass");
    upload(mDecay, FluidSystem::decayRatesOf(parameters, size()), "decay rates");
}

void ModalStepper::setState(const Eigen::VectorXd& v) {
    upload(mState, v, "state");
}
void ModalStepper::setForce(const Eigen::VectorXd& f) {
    upload(mForce, f, "force");
}

Eigen::VectorXd ModalStepper::state() const {
    std::vector<float> values(static_cast<std::size_t>(size()));
    mState.download<float>(values);
    return Eigen::Map<const Eigen::VectorXf>(values.data(), size()).template cast<double>();
}

DeviceStepStatus ModalStepper::status() const {
    shaders::ModalStatus raw{};
    mStatus.download<shaders::ModalStatus>(std::span(&raw, 1));
    if (mSettings.scheme != Integrator::Midpoint) return {0, 0.0, true, 0};
    return {int(raw.iterations), double(raw.residual), raw.converged != 0, int(raw.unconverged)};
}

void ModalStepper::recordUpdate(vulkan::CommandSequence& sequence, std::uint32_t op, std::uint32_t stage,
                                double h, bool indirect) const {
    const std::array<const vulkan::DeviceBuffer*, 10> buffers{
        &mState, &mPoint, &mWeighted,    &mRhs,    &mForce,
        &mMass,  &mDecay, &mAccumulator, &mStatus, &mArguments};
    const shaders::ModalUpdateParams params{
        std::uint32_t(size()), op, stage, mApplyDispatches + 1, float(h),
        mSettings.tolerance,   0,  0};
    if (indirect)
        // The update is the last dispatch of an iteration; its live entry follows the full copy.
        sequence.dispatchIndirect(
            mKernels.update, buffers, params, mArguments,
            VkDeviceSize(2 * mApplyDispatches + 1) * sizeof(VkDispatchIndirectCommand));
    else
        sequence.dispatch(mKernels.update, buffers, params, 1);
}

void ModalStepper::recordStep(vulkan::CommandSequence& sequence, double h, int substeps) const {
    if (substeps < 1) throw Error("modal step: substeps must be at least 1, got " + std::to_string(substeps));
    if (substeps > 1) {
        for (int s = 0; s < substeps; ++s) recordStep(sequence, h / substeps);
        return;
    }
    recordUpdate(sequence, MODAL_OP_BEGIN, 0, h, false);
    switch (mSettings.scheme) {
        case Integrator::Explicit:
            mCoefficients.recordApply(sequence, mKernels, mWeighted, mPoint, mRhs);
            recordUpdate(sequence, MODAL_OP_EXPLICIT, 0, h, false);
            break;
        case Integrator::Rk4:
            for (std::uint32_t stage = 0; stage < 4; ++stage) {
                mCoefficients.recordApply(sequence, mKernels, mWeighted, mPoint, mRhs);
                recordUpdate(sequence, MODAL_OP_RK4_STAGE, stage, h, false);
            }
            break;
        default:  // midpoint (the constructor refused the trapezoidal rule)
            for (int m = 0; m < mSettings.maxIterations; ++m) {
                mCoefficients.recordApply(sequence, mKernels, mWeighted, mPoint, mRhs,
                                          {&mArguments, mApplyDispatches + 1});
                recordUpdate(sequence, MODAL_OP_MIDPOINT, 0, h, true);
            }
            recordUpdate(sequence, MODAL_OP_MIDPOINT_END, 0, h, false);
            break;
    }
}

std::size_t ModalStepper::dispatchesPerStep() const {
    const std::size_t iteration = mApplyDispatches + 1;
    switch (mSettings.scheme) {
        case Integrator::Explicit:
            return 1 + iteration;
        case Integrator::Rk4:
            return 1 + 4 * iteration;
        default:
            return 2 + std::size_t(mSettings.maxIterations) * iteration;
    }
}

StepReport ModalStepper::step(double h) {
    if (!mStandalone) mStandalone = std::make_unique<vulkan::CommandSequence>(mContext);
    setForce(Eigen::VectorXd::Zero(size()));
    recordStep(*mStandalone, h);
    mStandalone->submitAndWait();
    const DeviceStepStatus status = this->status();
    return StepReport{status.iterations, 0, status.residual, status.converged};
}

}  // namespace modeflow::device
