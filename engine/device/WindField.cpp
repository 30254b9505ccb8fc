#include "engine/device/WindField.h"

#include <array>
#include <cstdint>  // the generated header uses uint32_t without including it
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"
#include "engine/device/DofFaces.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "shaders/WindParams.h"
#include "shaders/add_wind.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroup = 64;

}  // namespace

WindField::WindField(const vulkan::VulkanContext& context, const MacGrid& grid,
                     std::span<const double> base)
    : mGrid(grid),
      mBase(vulkan::DeviceBuffer::fromValues<float>(
          context, std::vector<float>(base.begin(), base.end()), "wind base flow")),
      mGroups(groupsFor(context, std::uint64_t(grid.faceTotal()), kWorkgroup)),
      mKernel(
          context,
          {"add_wind", add_wind_spv, 2, sizeof(shaders::WindParams), kWorkgroup, {}, {}, {}, {1}}) {
    requireFaceField(grid, base.size(), "wind base flow");
}

void WindField::record(vulkan::CommandSequence& sequence,
                       const vulkan::DeviceBuffer& faceField) const {
    requireWords("add_wind", faceField, std::uint64_t(mGrid.faceTotal()));
    shaders::WindParams params{};
    params.faceStart1 = std::uint32_t(mGrid.faceOffset(1));
    params.faceStart2 = std::uint32_t(mGrid.faceOffset(2));
    params.faceTotal = std::uint32_t(mGrid.faceTotal());
    params.periodic = mGrid.periodicBits();
    for (int a = 0; a < 3; ++a) params.cells[a] = std::uint32_t(mGrid.cells[a]);
    for (int side = 0; side < 6; ++side)
        if (mGrid.open[std::size_t(side)]) params.open |= 1u << side;
    const std::array<const vulkan::DeviceBuffer*, 2> buffers{&faceField, &mBase};
    sequence.dispatch(mKernel, buffers, params, mGroups);
}

}  // namespace modeflow::device
