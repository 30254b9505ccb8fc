#include "engine/device/SurfaceDye.h"

#include <algorithm>
#include <array>
// The generated headers use uint32_t without including <cstdint>.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SurfaceDyeParams.h"
#include "shaders/surface_dye_pairs.spv.h"
#include "shaders/surface_dye_step.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kPairsWorkgroup = 64;
/// Converged when |c − B x| ≤ 1e-6 |c| on the normal equations: float32's round-off leaves
/// residuals of a few 1e-7, and the dye is shown in colour, compared to 1e-4 (SurfaceDeviceTest).
constexpr float kTolerance = 1e-6f;

/// The solve is one workgroup: a CPU device runs its invocations in turn between barriers, so
/// fewer cost less there; a GPU wants more (as ModalKernels' update).
std::uint32_t stepWorkgroupSize(const vulkan::VulkanContext& context) {
    return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 64 : 256;
}

int scalarModes(const BasisCache& cache) {
    if (cache.kind != BasisKind::Surface) throw Error("surface dye: the basis is not a surface's");
    return int(cache.scalar.modes.cols());
}

/// Texels of a column of the advection coefficients: the pairs, in whole texels.
std::size_t columnTexels(int scalars) {
    return (pairCount(std::size_t(scalars)) + 3) / 4;
}

std::size_t floatBytes(std::size_t count) {
    return std::max<std::size_t>(count, 1) * sizeof(float);
}

}  // namespace

SurfaceDye::SurfaceDye(const vulkan::VulkanContext& context, const BasisCache& cache,
                       std::span<const SmokeEmitter> emitters)
    : mScalars(scalarModes(cache)),
      mModes(int(cache.surface.advection.cols())),
      mSources(cache, emitters),
      mPairsKernel(context, {"surface_dye_pairs",
                             surface_dye_pairs_spv,
                             4,
                             sizeof(shaders::SurfaceDyePairsParams),
                             kPairsWorkgroup,
                             {},
                             {0}}),
      mStepKernel(context, {"surface_dye_step", surface_dye_step_spv, 5,
                            sizeof(shaders::SurfaceDyeStepParams), stepWorkgroupSize(context)}),
      mPairs(context, floatBytes(pairCount(std::size_t(mScalars))), "surface dye pairs"),
      mState(context, floatBytes(std::size_t(mScalars) + 1), "surface dye"),
      mRate(context, floatBytes(std::size_t(mScalars) + 1), "surface dye rate"),
      mWork(context, floatBytes((5 + std::size_t(mScalars)) * std::size_t(mScalars)),
            "surface dye solve"),
      mStatus(context, sizeof(shaders::SurfaceDyeStatus), "surface dye status",
              vulkan::DeviceBuffer::Placement::HostVisible) {
    const std::size_t texels = columnTexels(mScalars);
    const std::size_t groups = (texels + kPairsWorkgroup - 1) / kPairsWorkgroup;
    const std::size_t bytes = texels * 4 * std::size_t(mModes) * sizeof(float);
    if (groups > context.properties().limits.maxComputeWorkGroupCount[0] ||
        bytes > context.texelBufferLimit())
        throw Error("surface dye: " + std::to_string(mScalars) + " scalar modes by " +
                    std::to_string(mModes) + " velocity modes (" + std::to_string(bytes) +
                    " bytes of advection coefficients) exceed the limits of " +
                    context.deviceName() + "; use fewer scalar_modes or --device cpu");
    if (texels > 0 && mModes > 0) {
        // One column of the pairs' coefficients per velocity mode, zero-padded to whole texels.
        Eigen::MatrixXf columns = Eigen::MatrixXf::Zero(Eigen::Index(4 * texels), mModes);
        columns.topRows(cache.surface.advection.rows()) = cache.surface.advection.cast<float>();
        mAdvection.emplace(vulkan::DeviceBuffer::fromValues<float>(
            context, std::span<const float>(columns.data(), std::size_t(columns.size())),
            "surface dye advection"));
    }
    setState(Eigen::VectorXd::Zero(mScalars + 1));
}

void SurfaceDye::setRate(double t) {
    const Eigen::VectorXd rate = mSources.rateAt(t);
    mRate.upload<float>(std::vector<float>(rate.begin(), rate.end()));
}

void SurfaceDye::recordStep(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& before,
                            const vulkan::DeviceBuffer& after, double h) const {
    if (mAdvection) {
        const std::array<const vulkan::DeviceBuffer*, 4> buffers{&*mAdvection, &before, &after,
                                                                 &mPairs};
        const auto pairs = std::uint32_t(pairCount(std::size_t(mScalars)));
        const auto texels = std::uint32_t(columnTexels(mScalars));
        sequence.dispatch(mPairsKernel, buffers,
                          shaders::SurfaceDyePairsParams{pairs, std::uint32_t(mModes), texels, 0},
                          (texels + kPairsWorkgroup - 1) / kPairsWorkgroup);
    } else {
        sequence.fill(mPairs, mPairs.bytes(), 0);  // no motion: K = 0
    }
    const std::array<const vulkan::DeviceBuffer*, 5> buffers{&mPairs, &mState, &mRate, &mWork,
                                                             &mStatus};
    // At most about M/2 iterations in exact arithmetic; float32's lost orthogonality takes more.
    const shaders::SurfaceDyeStepParams params{std::uint32_t(mScalars),
                                               std::uint32_t(mScalars) + 20, float(h), kTolerance};
    sequence.dispatch(mStepKernel, buffers, params, 1);
}

Eigen::VectorXd SurfaceDye::state() const {
    std::vector<float> values(std::size_t(mScalars) + 1);
    mState.download<float>(values);
    return Eigen::Map<const Eigen::VectorXf>(values.data(), Eigen::Index(values.size()))
        .cast<double>();
}

void SurfaceDye::setState(const Eigen::VectorXd& state) {
    if (state.size() != mScalars + 1)
        throw Error("surface dye: a state of " + std::to_string(state.size()) +
                    " values, expected " + std::to_string(mScalars + 1));
    const std::vector<float> values(state.begin(), state.end());
    mState.upload<float>(values);
}

SurfaceDyeStatus SurfaceDye::status() const {
    shaders::SurfaceDyeStatus status{};
    mStatus.download<shaders::SurfaceDyeStatus>(std::span(&status, 1));
    return {int(status.iterations), status.converged != 0, double(status.residual)};
}

}  // namespace modeflow::device
