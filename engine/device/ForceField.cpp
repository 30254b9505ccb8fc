#include "engine/device/ForceField.h"

#include <array>
#include <cstdint>  // the generated header uses uint32_t without including it
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/device/DofFaces.h"
#include "engine/device/SplatRecords.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ForceFieldParams.h"
#include "shaders/force_field.spv.h"

namespace modeflow::device {
namespace {

std::uint32_t checkedSplatCapacity(std::uint32_t maxSplats) {
    if (maxSplats < 1)
        throw Error("force_field: room for at least one splat is needed, got " +
                    std::to_string(maxSplats));
    return maxSplats;
}

}  // namespace

ForceFieldKernel::UpDofs ForceFieldKernel::uploadUpDofs(const vulkan::VulkanContext& context,
                                                        const MacGrid& grid,
                                                        const BasisCache& cache) {
    std::vector<std::uint32_t> entries;
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const FaceLocation face = locateFace(grid, cache.faces[d]);
        if (face.axis != upAxis(grid)) continue;
        entries.insert(entries.end(), {std::uint32_t(d), std::uint32_t(face.pos[0]),
                                       std::uint32_t(face.pos[1]), std::uint32_t(face.pos[2])});
    }
    const auto count = std::uint32_t(entries.size() / 4);
    if (entries.empty()) entries.resize(4, 0u);  // a buffer is never empty; count stays 0
    return {vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, entries, "up DOFs"), count};
}

ForceFieldKernel::ForceFieldKernel(const vulkan::VulkanContext& context, const BasisCache& cache,
                                   int scale, std::uint32_t maxSplats, std::uint32_t workgroupSize)
    : mGrid(MacGrid::fromSpec(cache.grid)),
      mSmoke(mGrid.refined(scale)),
      mScale(scale),
      mDofCount(std::uint32_t(cache.faces.size())),
      mMaxSplats(checkedSplatCapacity(maxSplats)),
      mGroups(groupsFor(context, cache.faces.size(), workgroupSize)),
      mFaces(uploadDofFaces(context, cache)),
      mUp(uploadUpDofs(context, mGrid, cache)),
      mSplats(context, VkDeviceSize(mMaxSplats) * sizeof(shaders::ForceSplatRecord),
              "force splats"),
      mKernels(context, {"force_field",
                         force_field_spv,
                         6,
                         sizeof(shaders::ForceFieldParams),
                         workgroupSize,
                         {},
                         {1},
                         {},
                         {2}}) {
    // Sized by the up list, not every DOF: on lavapipe each empty workgroup still costs a call.
    mUpGroups = groupsFor(context, mUp.count, workgroupSize);
}

const vulkan::ComputeKernel& ForceFieldKernel::kernel(std::uint32_t stage, bool useMask,
                                                      bool accumulate) const {
    return mKernels.with({stage, std::uint32_t(mGrid.dim), std::uint32_t(mScale), useMask ? 1u : 0u,
                          accumulate ? 1u : 0u});
}

void ForceFieldKernel::setSplats(std::span<const ForceSplat> splats) {
    const std::vector<shaders::ForceSplatRecord> records =
        splatRecords(splats, mMaxSplats, "force_field");
    mSplats.upload<shaders::ForceSplatRecord>(records);
    mSplatCount = std::uint32_t(splats.size());
}

void ForceFieldKernel::record(vulkan::CommandSequence& sequence, double buoyancy,
                              const vulkan::DeviceBuffer& temperature,
                              const vulkan::DeviceBuffer* fluidMask, const vulkan::DeviceBuffer& g,
                              bool upDofsOnly) const {
    const auto smokeCells = std::uint64_t(mSmoke.cellCount());
    requireWords("force_field", temperature, smokeCells);
    if (fluidMask) requireWords("force_field", *fluidMask, (smokeCells + 3) / 4);
    requireWords("force_field", g, mDofCount);

    shaders::ForceFieldParams params{};
    params.dofCount = mDofCount;
    params.upCount = mUp.count;
    params.splatCount = mSplatCount;
    params.faceStart1 = std::uint32_t(mGrid.faceOffset(1));
    params.faceStart2 = std::uint32_t(mGrid.faceOffset(2));
    params.buoyancy = float(buoyancy);
    params.periodic = mGrid.periodicBits();
    for (int a = 0; a < 3; ++a) {
        params.cells[a] = std::uint32_t(mGrid.cells[a]);
        params.origin[a] = float(mGrid.origin[a]);
        params.spacing[a] = float(mGrid.spacing[a]);
    }
    // Without a mask the temperature buffer fills the mask's binding; the shader never reads it.
    const std::array<const vulkan::DeviceBuffer*, 6> buffers{
        &mFaces, &mUp.buffer, &temperature, fluidMask ? fluidMask : &temperature, &mSplats, &g};
    const bool buoyant = buoyancy != 0.0 && mUp.count > 0;
    if (mSplatCount > 0)
        sequence.dispatch(kernel(FORCE_STAGE_SPLATS, false, false), buffers, params, mGroups);
    else if (!buoyant || !upDofsOnly)
        sequence.fill(g, VkDeviceSize(mDofCount) * sizeof(float), 0u);
    // After splats the buoyancy adds to g; otherwise it assigns the up DOFs (zeroed or unread).
    if (buoyant)
        sequence.dispatch(kernel(FORCE_STAGE_BUOYANCY, fluidMask != nullptr, mSplatCount > 0),
                          buffers, params, mUpGroups);
}

}  // namespace modeflow::device
