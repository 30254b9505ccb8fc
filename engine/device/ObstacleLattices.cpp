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

void ObstacleLattices::update(std::span<const MovingObstacle> obstacles) {
    std::vector<const SolidLevelSet*> sets;
    for (const MovingObstacle& o : obstacles) {
        if (o.levelSet) sets.push_back(o.levelSet.get());
        for (const auto& file : o.sequence)
            if (file.get() != o.levelSet.get()) sets.push_back(file.get());
    }
    if (sets == mUploaded) return;
    std::size_t total = 0;
    for (const SolidLevelSet* set : sets) total += set->depth.size() + set->velocity.size();
    if (total > std::size_t(std::numeric_limits<std::uint32_t>::max()))
        throw Error("the mesh obstacles' level sets hold " + std::to_string(total) +
                    " samples; the device takes at most " +
                    std::to_string(std::numeric_limits<std::uint32_t>::max()));
    std::vector<float> values;
    values.reserve(std::max<std::size_t>(total, 1));
    mPlaces.clear();
    for (const SolidLevelSet* set : sets) {
        LatticePlace place;
        place.depth = std::uint32_t(values.size());
        values.insert(values.end(), set->depth.begin(), set->depth.end());
        if (!set->velocity.empty()) {
            place.velocity = std::uint32_t(values.size());
            values.insert(values.end(), set->velocity.begin(), set->velocity.end());
        }
        mPlaces.emplace(set, place);
    }
    if (values.empty()) values.push_back(0.0f);
    mBuffer = vulkan::DeviceBuffer::fromValues<float>(mContext, values, "obstacle lattices");
    mUploaded = std::move(sets);
}

LatticePlace ObstacleLattices::placeOf(const SolidLevelSet* set) const {
    const auto found = mPlaces.find(set);
    return found == mPlaces.end() ? LatticePlace{} : found->second;
}

}  // namespace modeflow::device
