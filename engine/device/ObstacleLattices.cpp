#include "engine/device/ObstacleLattices.h"

#include <algorithm>
#include <limits>
#include <string>

#include "engine/core/Error.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::device {
namespace {

/// `values` padded with zeros to whole texels (at least one: the kernels bind the texel view).
vulkan::DeviceBuffer latticeBuffer(const vulkan::VulkanContext& context,
                                   std::vector<float> values) {
    constexpr std::size_t perTexel = vulkan::DeviceBuffer::kTexelBytes / sizeof(float);
    values.resize(std::max<std::size_t>((values.size() + perTexel - 1) / perTexel, 1) * perTexel,
                  0.0f);
    return vulkan::DeviceBuffer::fromValues<float>(context, values, "obstacle lattices");
}

}  // namespace

ObstacleLattices::ObstacleLattices(const vulkan::VulkanContext& context)
    : mContext(context), mBuffer(latticeBuffer(context, {})) {}

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
    // One value a texel of the R32UI view, within a storage buffer, less the padding.
    const std::size_t limit =
        std::min<std::size_t>({std::numeric_limits<std::uint32_t>::max(),
                               mContext.properties().limits.maxTexelBufferElements,
                               std::size_t(mContext.storageBufferLimit() / sizeof(float))}) -
        4;
    if (total > limit)
        throw Error("the mesh obstacles' level sets hold " + std::to_string(total) + " samples; " +
                    mContext.deviceName() + " takes at most " + std::to_string(limit) +
                    " (coarser lattices: fewer or smaller meshes)");
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
    mBuffer = latticeBuffer(mContext, std::move(values));
    ++mGeneration;
    mUploaded = std::move(sets);
}

LatticePlace ObstacleLattices::placeOf(const SolidLevelSet* set) const {
    const auto found = mPlaces.find(set);
    return found == mPlaces.end() ? LatticePlace{} : found->second;
}

}  // namespace modeflow::device
