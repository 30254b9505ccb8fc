#include "engine/device/WindField.h"

#include <array>
#include <cmath>
#include <cstdint>  // the generated header uses uint32_t without including it

#include "engine/core/Error.h"
#include "engine/device/DofFaces.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "shaders/WindParams.h"
#include "shaders/add_wind.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroup = 64;

const Vec3& finite(const Vec3& wind) {
    for (const double u : wind)
        if (!std::isfinite(u)) throw Error("wind: the velocity is not finite");
    return wind;
}

}  // namespace

WindField::WindField(const vulkan::VulkanContext& context, const MacGrid& grid, const Vec3& wind)
    : mGrid(grid),
      mWind(finite(wind)),
      mGroups(groupsFor(context, std::uint64_t(grid.faceTotal()), kWorkgroup)),
      mKernel(context, {"add_wind", add_wind_spv, 1, sizeof(shaders::WindParams), kWorkgroup}) {}

void WindField::record(vulkan::CommandSequence& sequence,
                       const vulkan::DeviceBuffer& faceField) const {
    requireWords("add_wind", faceField, std::uint64_t(mGrid.faceTotal()));
    shaders::WindParams params{};
    params.faceStart1 = std::uint32_t(mGrid.faceOffset(1));
    params.faceStart2 = std::uint32_t(mGrid.faceOffset(2));
    params.faceTotal = std::uint32_t(mGrid.faceTotal());
    params.periodic = mGrid.periodicBits();
    for (int a = 0; a < 3; ++a) params.cells[a] = std::uint32_t(mGrid.cells[a]);
    for (int a = 0; a < 3; ++a) params.wind[a] = a < mGrid.dim ? float(mWind[a]) : 0.0f;
    const std::array<const vulkan::DeviceBuffer*, 1> buffers{&faceField};
    sequence.dispatch(mKernel, buffers, params, mGroups);
}

}  // namespace modeflow::device
