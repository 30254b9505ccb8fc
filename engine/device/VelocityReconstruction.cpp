#include "engine/device/VelocityReconstruction.h"

#include <array>
#include <cstdint>  // the generated header uses uint32_t without including it
#include <limits>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/device/DofFaces.h"
#include "engine/device/ModeBuffer.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ReconstructVelocityParams.h"
#include "shaders/reconstruct_velocity.spv.h"

namespace modeflow::device {
namespace {

static_assert(ModeBuffer::kTileLanes == MODE_TILE_LANES && ModeBuffer::kTileRows == MODE_TILE_ROWS,
              "the shader reads the tiles ModeBuffer writes");
/// Units (32-byte words of a tile) per invocation at least, on a CPU device: each invocation first
/// reads the chunk's coefficients (one load a quad of modes on lavapipe, for every lane), which
/// many units then share. A GPU gets one invocation per unit.
constexpr std::uint64_t kCpuUnitsPerInvocation = 16;

/// cache.faces as uint32 face numbers (uploadDofFaces' checks), zero-padded to whole tiles of
/// float16 modes: the kernel reads them four at a time for each tile row (padded DOFs are not
/// written).
vulkan::DeviceBuffer paddedDofFaces(const vulkan::VulkanContext& context, const BasisCache& cache) {
    const std::int64_t faceTotal = MacGrid::fromSpec(cache.grid).faceTotal();
    if (cache.faces.empty()) throw Error("velocity DOFs: the basis has no face DOFs");
    if (faceTotal > std::int64_t(std::numeric_limits<std::uint32_t>::max()))
        throw Error("velocity DOFs: " + std::to_string(faceTotal) +
                    " grid faces do not fit the kernels' 32-bit face numbers");
    const std::size_t perTile =
        std::size_t(ModeBuffer::kTileVectors) * ModeBuffer::dofsPerVector(ModePrecision::Float16);
    std::vector<std::uint32_t> faces((cache.faces.size() + perTile - 1) / perTile * perTile, 0u);
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        if (cache.faces[d] < 0 || cache.faces[d] >= faceTotal)
            throw Error("velocity DOFs: DOF " + std::to_string(d) + " names face " +
                        std::to_string(cache.faces[d]) + ", outside the grid's " +
                        std::to_string(faceTotal) + " faces");
        faces[d] = std::uint32_t(cache.faces[d]);
    }
    return vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, faces, "DOF faces (padded)");
}

}  // namespace

ReconstructionKernel::ReconstructionKernel(const vulkan::VulkanContext& context,
                                           const BasisCache& cache, std::uint32_t workgroupSize)
    : mContext(context.requireShaderInt64("the velocity reconstruction")),
      mGrid(MacGrid::fromSpec(cache.grid)),
      mDofCount(std::uint32_t(cache.faces.size())),
      mFaces(paddedDofFaces(context, cache)),
      mScratch(context, mFaces.bytes(), "reconstruction sums"),
      mWorkgroupSize(workgroupSize),
      mKernels(context, {"reconstruct_velocity",
                         reconstruct_velocity_spv,
                         6,
                         sizeof(shaders::ReconstructVelocityParams),
                         workgroupSize,
                         {},
                         {0, 3}}) {}

vulkan::DeviceBuffer ReconstructionKernel::makeFaceField(std::string name) const {
    const std::vector<float> zeros(std::size_t(mGrid.faceTotal()), 0.0f);
    return vulkan::DeviceBuffer::fromValues<float>(mContext, zeros, std::move(name));
}

std::vector<std::uint32_t> ReconstructionKernel::dispatchGroups(const ModeBuffer& modes) const {
    // Units: kTileRows vectors of a tile, one 32-byte word (ModeAccess.glsl).
    const std::uint64_t units = std::uint64_t(modes.tileCount()) * ModeBuffer::kTileLanes;
    const bool cpu = mContext.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const std::uint32_t groups = groupsFor(
        mContext, cpu ? (units + kCpuUnitsPerInvocation - 1) / kCpuUnitsPerInvocation : units,
        mWorkgroupSize);
    return std::vector<std::uint32_t>(modes.chunks().size(), groups);
}

void ReconstructionKernel::record(vulkan::CommandSequence& sequence, const ModeBuffer& modes,
                                  const vulkan::DeviceBuffer& v,
                                  const vulkan::DeviceBuffer& faceField,
                                  IndirectArguments indirect) const {
    if (modes.dofCount() != mDofCount)
        throw Error("reconstruct_velocity: the modes have " + std::to_string(modes.dofCount()) +
                    " DOFs, the kernel's basis " + std::to_string(mDofCount));
    requireWords("reconstruct_velocity", v, modes.paddedModeCount());
    requireWords("reconstruct_velocity", faceField, std::uint64_t(mGrid.faceTotal()));

    shaders::ReconstructVelocityParams params{};
    params.dofCount = mDofCount;
    params.tileCount = modes.tileCount();
    params.faceStart1 = std::uint32_t(mGrid.faceOffset(1));
    params.faceStart2 = std::uint32_t(mGrid.faceOffset(2));
    for (int a = 0; a < 3; ++a) params.inverseArea[a] = float(1.0 / mGrid.faceArea(a));
    const std::vector<std::uint32_t> groups = dispatchGroups(modes);
    std::uint32_t d = 0;
    for (const ModeBuffer::Chunk& chunk : modes.chunks()) {
        params.firstMode = chunk.firstMode;
        const bool first = &chunk == &modes.chunks().front(),
                   last = &chunk == &modes.chunks().back();
        // Float16 modes, a chunk after the first, the last chunk, its mode count, first mode % 4.
        const std::vector<std::uint32_t> constants{modes.precision() == ModePrecision::Float16,
                                                   !first, last, chunk.modeCount,
                                                   chunk.firstMode % 4};
        const std::array<const vulkan::DeviceBuffer*, 6> buffers{
            &chunk.buffer, &modes.scales(), &v, &mFaces, &faceField, &mScratch};
        indirect.after(d).dispatch(sequence, mKernels.with(constants), buffers, params, groups[d]);
        ++d;
    }
}

}  // namespace modeflow::device
