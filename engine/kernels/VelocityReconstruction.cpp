#include "engine/kernels/VelocityReconstruction.h"

#include <array>
#include <cstdint>  // the generated header uses uint32_t without including it
#include <vector>

#include "engine/format/Error.h"
#include "engine/kernels/DofFaces.h"
#include "engine/kernels/ModeBuffer.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ReconstructVelocityParams.h"
#include "shaders/reconstruct_velocity.spv.h"

namespace modeflow::vulkan {

ReconstructionKernel::ReconstructionKernel(const VulkanContext& context, const BasisCache& cache,
                                           std::uint32_t workgroupSize)
    : mContext(context),
      mGrid(MacGrid::fromSpec(cache.grid)),
      mDofCount(std::uint32_t(cache.faces.size())),
      mGroups(groupsFor(context, cache.faces.size(), workgroupSize)),
      mFaces(uploadDofFaces(context, cache)),
      mKernel(context, ComputeKernelSpec{"reconstruct_velocity", reconstruct_velocity_spv, 5,
                                         sizeof(shaders::ReconstructVelocityParams), workgroupSize}) {}

DeviceBuffer ReconstructionKernel::makeFaceField(std::string name) const {
    const std::vector<float> zeros(std::size_t(mGrid.faceTotal()), 0.0f);
    return DeviceBuffer::fromValues<float>(mContext, zeros, std::move(name));
}

void ReconstructionKernel::record(CommandSequence& sequence, const ModeBuffer& modes, const DeviceBuffer& v,
                                  const DeviceBuffer& faceField) const {
    if (modes.dofCount() != mDofCount)
        throw Error("reconstruct_velocity: the modes have " + std::to_string(modes.dofCount()) +
                    " DOFs, the kernel's basis " + std::to_string(mDofCount));
    requireWords("reconstruct_velocity", v, modes.paddedModeCount());
    requireWords("reconstruct_velocity", faceField, std::uint64_t(mGrid.faceTotal()));

    shaders::ReconstructVelocityParams params{};
    params.dofCount = mDofCount;
    params.modeStride = modes.modeStride();
    params.halfPrecision = modes.precision() == ModePrecision::Float16;
    params.faceStart1 = std::uint32_t(mGrid.faceOffset(1));
    params.faceStart2 = std::uint32_t(mGrid.faceOffset(2));
    for (int a = 0; a < 3; ++a) params.inverseArea[a] = float(1.0 / mGrid.faceArea(a));
    for (const ModeBuffer::Chunk& chunk : modes.chunks()) {
        params.firstMode = chunk.firstMode;
        params.modeCount = chunk.modeCount;
        params.accumulate = chunk.firstMode > 0;
        const std::array<const DeviceBuffer*, 5> buffers{&chunk.buffer, &modes.scales(), &v, &mFaces, &faceField};
        sequence.dispatch(mKernel, buffers, params, mGroups);
    }
}

}  // namespace modeflow::vulkan
