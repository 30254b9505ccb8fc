#include "engine/device/ForceProjection.h"

#include <algorithm>
#include <array>
#include <cstdint>  // the generated headers use uint32_t without including it
#include <numeric>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/device/DofFaces.h"
#include "engine/device/ModeBuffer.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ProjectForceParams.h"
#include "shaders/project_force.spv.h"
#include "shaders/project_force_sum.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kModesPerGroup = PROJECT_FORCE_MODES_PER_GROUP;
static_assert(ModeBuffer::kTileLanes == MODE_TILE_LANES && ModeBuffer::kTileRows == MODE_TILE_ROWS,
              "the shader reads the tiles ModeBuffer writes");
/// Default DOFs per workgroup of pass 1. A GPU wants many workgroups (a 64³ basis, ~750k DOFs,
/// makes ~380 blocks). A CPU device wants few, large ones: lavapipe runs each workgroup's closing
/// shared-memory sums invocation by invocation (32768 measured faster than 8192 there, when
/// they were a tree), but still about kCpuGroups of them to share among its threads.
constexpr std::uint32_t kGpuDofsPerGroup = 2048;
constexpr std::uint32_t kCpuMinDofsPerGroup = 4096, kCpuMaxDofsPerGroup = 32768, kCpuGroups = 16;
/// DOFs of a tile of float16 modes: blocks are whole tiles of either precision.
constexpr std::uint32_t kTileDofs = ModeBuffer::kTileVectors * 8;

std::uint32_t modeGroups(std::uint32_t modes) {
    return (modes + kModesPerGroup - 1) / kModesPerGroup;
}

/// Mode slots of a workgroup (the shader's MODES) for a chunk of `modes`: the chunk split into
/// equal groups of at most kModesPerGroup, rounded up to 4, so that few slots go unused (lavapipe
/// still loops over an unused slot's lanes). Larger groups on a CPU device, their closing sums in
/// rounds of 64, measured slower with float32 modes (sums spilled; engine/README.md "Speed").
std::uint32_t slotsFor(std::uint32_t modes) {
    const std::uint32_t groups = modeGroups(modes);
    return ((modes + groups - 1) / groups + 3) / 4 * 4;
}

/// DOFs per block: the wish rounded up to whole float16 tiles, and to a whole number of units
/// (16 float16 DOFs) per invocation, raised until every chunk's dispatch (at most all modes) stays
/// within the device's group count limit.
std::uint32_t blockSizeFor(const vulkan::VulkanContext& context, std::uint32_t dofs,
                           std::uint32_t modes, const ForceProjectionOptions& options) {
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const std::uint64_t maxGroups = limits.maxComputeWorkGroupCount[0];
    if (modes == 0) throw Error("project_force: the basis has no modes");
    if (modes > maxGroups)
        throw Error("project_force: " + std::to_string(modes) + " modes exceed the device's " +
                    std::to_string(maxGroups) + " workgroups per dispatch");
    const std::uint32_t size = options.workgroupSize;
    if (size == 0) throw Error("project_force: the workgroup size must be positive");
    // project_force.comp keeps kModesPerGroup sums per invocation in shared memory.
    const std::uint64_t shared = std::uint64_t(size) * kModesPerGroup * sizeof(float);
    if (shared > limits.maxComputeSharedMemorySize)
        throw Error("project_force: workgroups of " + std::to_string(size) + " need " +
                    std::to_string(shared) + " bytes of shared memory, more than the " +
                    std::to_string(limits.maxComputeSharedMemorySize) + " of " +
                    context.deviceName());
    std::uint64_t wanted = options.dofsPerGroup > 0 ? options.dofsPerGroup : kGpuDofsPerGroup;
    if (options.dofsPerGroup == 0 && context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
        wanted = std::clamp<std::uint64_t>(std::uint64_t(dofs) * modeGroups(modes) / kCpuGroups,
                                           kCpuMinDofsPerGroup, kCpuMaxDofsPerGroup);
    const std::uint64_t maxBlocks = std::max<std::uint64_t>(1, maxGroups / modeGroups(modes));
    const std::uint64_t block = std::max(wanted, (std::uint64_t(dofs) + maxBlocks - 1) / maxBlocks);
    const std::uint64_t unit = std::lcm<std::uint64_t>(
        kTileDofs, std::uint64_t(size) * kTileDofs / ModeBuffer::kTileLanes);
    return std::uint32_t((block + unit - 1) / unit * unit);
}

/// The weights, zero-padded to whole float16 tiles like the modes (read eight at a time; a padded
/// DOF adds 0).
vulkan::DeviceBuffer weightBuffer(const vulkan::VulkanContext& context, const BasisCache& cache,
                                  FaceQuantity quantity) {
    const Eigen::VectorXd w = projectionWeights(cache, quantity);
    std::vector<float> values(w.begin(), w.end());
    values.resize((values.size() + kTileDofs - 1) / kTileDofs * kTileDofs, 0.0f);
    return vulkan::DeviceBuffer::fromValues<float>(context, values, "projection weights");
}

}  // namespace

ForceProjectionKernel::ForceProjectionKernel(const vulkan::VulkanContext& context,
                                             const BasisCache& cache, FaceQuantity quantity,
                                             const ForceProjectionOptions& options)
    : mGather(quantity == FaceQuantity::FaceField && !options.dofOrder),
      mDofCount(std::uint32_t(cache.faces.size())),
      mModeCount(std::uint32_t(cache.velocity.eigenvalues.size())),
      mFaceTotal(std::uint64_t(MacGrid::fromSpec(cache.grid).faceTotal())),
      mBlockSize(blockSizeFor(context, mDofCount, mModeCount, options)),
      mBlockCount((mDofCount + mBlockSize - 1) / mBlockSize),
      mFaces(uploadDofFaces(context, cache)),
      mWeights(weightBuffer(context, cache, quantity)),
      mPartials(context,
                std::max<VkDeviceSize>(1, VkDeviceSize(mModeCount) * mBlockCount) * sizeof(float),
                "projection partial sums"),
      mContext(context),
      mWorkgroupSize(options.workgroupSize),
      mPartialKernels(context, {"project_force",
                                project_force_spv,
                                6,
                                sizeof(shaders::ProjectForceParams),
                                options.workgroupSize,
                                {},
                                {0, 1, 2}}),
      mSumKernel(context, vulkan::ComputeKernelSpec{"project_force_sum", project_force_sum_spv, 3,
                                                    sizeof(shaders::ProjectForceSumParams),
                                                    options.workgroupSize}) {}

std::vector<std::uint32_t> ForceProjectionKernel::dispatchGroups(const ModeBuffer& modes) const {
    std::vector<std::uint32_t> groups;
    for (const ModeBuffer::Chunk& chunk : modes.chunks()) {
        const std::uint32_t slots = slotsFor(chunk.modeCount);
        groups.push_back((chunk.modeCount + slots - 1) / slots * mBlockCount);
    }
    groups.push_back(groupsFor(mContext, mModeCount, mWorkgroupSize));
    return groups;
}

void ForceProjectionKernel::record(vulkan::CommandSequence& sequence, const ModeBuffer& modes,
                                   const vulkan::DeviceBuffer& q, const vulkan::DeviceBuffer& f,
                                   IndirectArguments indirect) const {
    if (modes.dofCount() != mDofCount || modes.modeCount() != mModeCount)
        throw Error("project_force: the modes are " + std::to_string(modes.modeCount()) + " on " +
                    std::to_string(modes.dofCount()) + " DOFs, the kernel's basis " +
                    std::to_string(mModeCount) + " on " + std::to_string(mDofCount));
    requireWords("project_force", q, mGather ? mFaceTotal : mDofCount);
    requireWords("project_force", f, mModeCount);

    shaders::ProjectForceParams params{};
    params.dofCount = mDofCount;
    params.tileCount = modes.tileCount();
    params.blockCount = mBlockCount;
    params.blockTiles = mBlockSize / (ModeBuffer::kTileVectors * modes.dofsPerVector());
    const std::vector<std::uint32_t> groups = dispatchGroups(modes);
    std::uint32_t d = 0;
    for (const ModeBuffer::Chunk& chunk : modes.chunks()) {
        params.firstMode = chunk.firstMode;
        params.modeCount = chunk.modeCount;
        const std::uint32_t slots = slotsFor(chunk.modeCount);
        // q twice: its whole texels (binding 1) and one float at a time (binding 5).
        const std::array<const vulkan::DeviceBuffer*, 6> buffers{
            &chunk.buffer, &q, &mWeights, &mFaces, &mPartials, &q};
        indirect.after(d).dispatch(sequence, partialKernel(modes.precision(), slots), buffers,
                                   params, groups[d]);
        ++d;
    }
    const shaders::ProjectForceSumParams sum{mModeCount, mBlockCount, 0, 0};
    const std::array<const vulkan::DeviceBuffer*, 3> buffers{&mPartials, &modes.scales(), &f};
    indirect.after(d).dispatch(sequence, mSumKernel, buffers, sum, groups[d]);
}

const vulkan::ComputeKernel& ForceProjectionKernel::partialKernel(ModePrecision precision,
                                                                  std::uint32_t slots) const {
    return mPartialKernels.with(
        {std::uint32_t(precision == ModePrecision::Float16), mGather ? 1u : 0u, slots});
}

}  // namespace modeflow::device
