#include "engine/device/ObstacleLattices.h"

#include <algorithm>
#include <limits>
#include <string>

#include "engine/core/Error.h"

namespace modeflow::device {

ObstacleLattices::ObstacleLattices(const vulkan::VulkanContext& context)
    : mContext(context),
      mBuffer(vulkan::DeviceBuffer::fromValues<float>(context, std::vector<float>{0.0f},
                                                      "obstacle lattices")) {}

std::vector<std::uint32_t> ObstacleLattices::update(std::span<const MovingObstacle> obstacles) {
    std::vector<const SolidLevelSet*> sets;
    std::vector<std::uint32_t> starts;
    std::size_t total = 0;
    for (const MovingObstacle& o : obstacles) {
        sets.push_back(o.levelSet.get());
        starts.push_back(std::uint32_t(total));
        if (o.levelSet) total += o.levelSet->depth.size();
    }
    if (total > std::size_t(std::numeric_limits<std::uint32_t>::max()))
        throw Error("the mesh obstacles' level sets hold " + std::to_string(total) +
                    " samples; the device takes at most " +
                    std::to_string(std::numeric_limits<std::uint32_t>::max()));
    if (sets != mUploaded) {
        std::vector<float> depth;
        depth.reserve(std::max<std::size_t>(total, 1));
        for (const SolidLevelSet* set : sets)
            if (set) depth.insert(depth.end(), set->depth.begin(), set->depth.end());
        if (depth.empty()) depth.push_back(0.0f);
        mBuffer = vulkan::DeviceBuffer::fromValues<float>(mContext, depth, "obstacle lattices");
        mUploaded = std::move(sets);
    }
    return starts;
}

}  // namespace modeflow::device
