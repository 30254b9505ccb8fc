#include "engine/kernels/ForceProjection.h"

#include <algorithm>
#include <array>
#include <cstdint>  // the generated headers use uint32_t without including it
#include <vector>

#include "engine/field/MacGrid.h"
#include "engine/format/Error.h"
#include "engine/kernels/DofFaces.h"
#include "engine/kernels/ModeBuffer.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ProjectForceParams.h"
#include "shaders/project_force.spv.h"
#include "shaders/project_force_sum.spv.h"

namespace modeflow::vulkan {
namespace {

constexpr std::uint32_t kModesPerGroup = PROJECT_FORCE_MODES_PER_GROUP;

std::uint32_t modeGroups(std::uint32_t modes) { return (modes + kModesPerGroup - 1) / kModesPerGroup; }

/// DOFs per block: the wish rounded up to whole workgroups, raised until every chunk's
/// dispatch (at most all modes) stays within the device's group count limit.
std::uint32_t blockSizeFor(const VulkanContext& context, std::uint32_t dofs, std::uint32_t modes,
                           const ForceProjectionOptions& options) {
    const std::uint64_t maxGroups = context.properties().limits.maxComputeWorkGroupCount[0];
    if (modes == 0) throw Error("project_force: the basis has no modes");
    if (modes > maxGroups)
        throw Error("project_force: " + std::to_string(modes) + " modes exceed the device's " +
                    std::to_string(maxGroups) + " workgroups per dispatch");
    const std::uint32_t size = options.workgroupSize;
    if (size == 0) throw Error("project_force: the workgroup size must be positive");
    const std::uint64_t wanted = std::max<std::uint64_t>(options.dofsPerGroup, 1);
    const std::uint64_t maxBlocks = std::max<std::uint64_t>(1, maxGroups / modeGroups(modes));
    const std::uint64_t block = std::max(wanted, (std::uint64_t(dofs) + maxBlocks - 1) / maxBlocks);
    return std::uint32_t((block + size - 1) / size * size);
}

DeviceBuffer weightBuffer(const VulkanContext& context, const BasisCache& cache, FaceQuantity quantity) {
    const Eigen::VectorXd w = projectionWeights(cache, quantity);
    const std::vector<float> values(w.begin(), w.end());
    return DeviceBuffer::fromValues<float>(context, values, "projection weights");
}

}  // namespace

ForceProjectionKernel::ForceProjectionKernel(const VulkanContext& context, const BasisCache& cache,
                                             FaceQuantity quantity, const ForceProjectionOptions& options)
    : mQuantity(quantity),
      mDofCount(std::uint32_t(cache.faces.size())),
      mModeCount(std::uint32_t(cache.velocity.modes.cols())),
      mFaceTotal(std::uint64_t(MacGrid::fromSpec(cache.grid).faceTotal())),
      mBlockSize(blockSizeFor(context, mDofCount, mModeCount, options)),
      mBlockCount((mDofCount + mBlockSize - 1) / mBlockSize),
      mFaces(uploadDofFaces(context, cache)),
      mWeights(weightBuffer(context, cache, quantity)),
      mPartials(context, std::max<VkDeviceSize>(1, VkDeviceSize(mModeCount) * mBlockCount) * sizeof(float),
                "projection partial sums"),
      mPartialKernel(context, ComputeKernelSpec{"project_force", project_force_spv, 5,
                                                sizeof(shaders::ProjectForceParams), options.workgroupSize}),
      mSumKernel(context, ComputeKernelSpec{"project_force_sum", project_force_sum_spv, 3,
                                            sizeof(shaders::ProjectForceSumParams), options.workgroupSize}) {}

void ForceProjectionKernel::record(CommandSequence& sequence, const ModeBuffer& modes, const DeviceBuffer& q,
                                   const DeviceBuffer& f) const {
    if (modes.dofCount() != mDofCount || modes.modeCount() != mModeCount)
        throw Error("project_force: the modes are " + std::to_string(modes.modeCount()) + " on " +
                    std::to_string(modes.dofCount()) + " DOFs, the kernel's basis " + std::to_string(mModeCount) +
                    " on " + std::to_string(mDofCount));
    requireWords("project_force", q, mQuantity == FaceQuantity::FaceField ? mFaceTotal : mDofCount);
    requireWords("project_force", f, mModeCount);

    shaders::ProjectForceParams params{};
    params.dofCount = mDofCount;
    params.modeStride = modes.modeStride();
    params.halfPrecision = modes.precision() == ModePrecision::Float16;
    params.gatherFaces = mQuantity == FaceQuantity::FaceField;
    params.blockCount = mBlockCount;
    params.blockSize = mBlockSize;
    for (const ModeBuffer::Chunk& chunk : modes.chunks()) {
        params.firstMode = chunk.firstMode;
        params.modeCount = chunk.modeCount;
        const std::array<const DeviceBuffer*, 5> buffers{&chunk.buffer, &q, &mWeights, &mFaces, &mPartials};
        sequence.dispatch(mPartialKernel, buffers, params, modeGroups(chunk.modeCount) * mBlockCount);
    }
    const shaders::ProjectForceSumParams sum{mModeCount, mBlockCount, 0, 0};
    const std::array<const DeviceBuffer*, 3> buffers{&mPartials, &modes.scales(), &f};
    sequence.dispatch(mSumKernel, buffers, sum, mModeCount);
}

}  // namespace modeflow::vulkan
