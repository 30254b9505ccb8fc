#include "engine/device/DofFaces.h"

#include <algorithm>
#include <limits>
#include <thread>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::device {
namespace {

/// Workgroups per CPU thread of a CPU device's dispatch (groupCap).
constexpr std::uint64_t kCpuGroupsPerThread = 16;

}  // namespace

namespace {

/// cache.faces as uint32 face numbers, checked against the grid.
std::vector<std::uint32_t> checkedDofFaces(const BasisCache& cache, const MacGrid& grid) {
    if (cache.faces.empty()) throw Error("velocity DOFs: the basis has no face DOFs");
    if (grid.faceTotal() > std::int64_t(std::numeric_limits<std::uint32_t>::max()))
        throw Error("velocity DOFs: " + std::to_string(grid.faceTotal()) +
                    " grid faces do not fit the kernels' 32-bit face numbers");
    std::vector<std::uint32_t> faces(cache.faces.size());
    for (std::size_t d = 0; d < faces.size(); ++d) {
        if (cache.faces[d] < 0 || cache.faces[d] >= grid.faceTotal())
            throw Error("velocity DOFs: DOF " + std::to_string(d) + " names face " +
                        std::to_string(cache.faces[d]) + ", outside the grid's " +
                        std::to_string(grid.faceTotal()) + " faces");
        faces[d] = std::uint32_t(cache.faces[d]);
    }
    return faces;
}

}  // namespace

vulkan::DeviceBuffer uploadDofFaces(const vulkan::VulkanContext& context, const BasisCache& cache) {
    const std::vector<std::uint32_t> faces = checkedDofFaces(cache, MacGrid::fromSpec(cache.grid));
    return vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, faces, "DOF faces");
}

vulkan::DeviceBuffer uploadFaceDofs(const vulkan::VulkanContext& context, const BasisCache& cache,
                                    std::uint32_t none) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const std::vector<std::uint32_t> faces = checkedDofFaces(cache, grid);
    std::vector<std::uint32_t> dofs(std::size_t(grid.faceTotal()), none);
    for (std::size_t d = 0; d < faces.size(); ++d) dofs[faces[d]] = std::uint32_t(d);
    return vulkan::DeviceBuffer::fromValues<std::uint32_t>(context, dofs, "DOF of each face");
}

std::uint32_t groupCap(const vulkan::VulkanContext& context) {
    const std::uint32_t limit = context.properties().limits.maxComputeWorkGroupCount[0];
    // A CPU device runs each workgroup as a call with its own set-up: a few per thread keep
    // its threads busy, and more only add calls (measured on a buoyancy pass of the 64^3 box:
    // precompute/README.md "Closed-form bases").
    if (context.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) return limit;
    static const std::uint64_t threads = std::max(1u, std::thread::hardware_concurrency());
    return std::uint32_t(std::min<std::uint64_t>(limit, kCpuGroupsPerThread * threads));
}

std::uint32_t groupsFor(const vulkan::VulkanContext& context, std::uint64_t items,
                        std::uint32_t workgroupSize) {
    const std::uint64_t wanted =
        std::max<std::uint64_t>(1, (items + workgroupSize - 1) / workgroupSize);
    return std::uint32_t(std::min<std::uint64_t>(wanted, groupCap(context)));
}

void requireWords(const std::string& kernel, const vulkan::DeviceBuffer& buffer,
                  std::uint64_t count) {
    if (buffer.bytes() < count * 4)
        throw Error(kernel + ": buffer \"" + buffer.name() + "\" holds " +
                    std::to_string(buffer.bytes()) + " bytes, " + std::to_string(count * 4) +
                    " needed");
}

}  // namespace modeflow::device
