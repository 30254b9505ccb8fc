#include "engine/device/SmokeDisplacement.h"

#include <algorithm>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/device/ObstacleRecords.h"
#include "engine/device/SmokeState.h"
#include "engine/simulation/SmokeDisplacement.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SmokeDisplaceParams.h"
#include "shaders/smoke_displace.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroupSize = 64;
/// Stamps live in the top 24 bits of the cover and target words.
constexpr std::uint32_t kStampLimit = 1u << 24;

vulkan::DeviceBuffer zeroWords(const vulkan::VulkanContext& context, std::int64_t count,
                               const char* name) {
    return vulkan::DeviceBuffer::fromValues<std::uint32_t>(
        context, std::vector<std::uint32_t>(std::size_t(std::max<std::int64_t>(count, 1)), 0u),
        name);
}

}  // namespace

SmokeDisplacement::SmokeDisplacement(const vulkan::VulkanContext& context, const SmokeState& state)
    : mContext(context),
      mPoses(context,
             std::size_t(maxDisplacementSubsteps) * maxObstacles * sizeof(shaders::ObstacleRecord),
             "solid poses"),
      mCover(zeroWords(context, state.cellCount(), "smoke cover")),
      mTarget(zeroWords(context, state.cellCount(), "smoke push targets")),
      mWork(zeroWords(context, 8, "smoke displacement work")),
      mCovered(zeroWords(context, state.cellCount(), "covered smoke cells")),
      mReceivers(zeroWords(context, state.cellCount(), "smoke cells receiving")),
      mLattices(context),
      // Constants: the stage, the solid kinds. Records as texels (binding 0), lattices and mask
      // as values (1, 2): shaders/ObstacleShape.glsl.
      mStages(context, {"smoke_displace",
                        smoke_displace_spv,
                        12,
                        sizeof(shaders::SmokeDisplaceParams),
                        kWorkgroupSize,
                        {},
                        {0},
                        {},
                        {1, 2}}) {}

void SmokeDisplacement::record(vulkan::CommandSequence& sequence, SmokeState& state,
                               std::span<const MovingObstacle> solids, double t, double dt) {
    if (solids.empty()) return;
    if (solids.size() > std::size_t(maxObstacles))
        throw Error("smoke displacement: " + std::to_string(solids.size()) + " solids, at most " +
                    std::to_string(maxObstacles));
    requireLevelSets(solids);
    const MacGrid& grid = state.smokeGrid();
    const int substeps = displacementSubsteps(solids, t, dt, grid);
    const std::uint32_t kinds = solidKinds(solids);
    mLattices.update(solids);

    std::vector<ObstaclePose> poses(solids.size());
    std::vector<std::vector<CellBox>> boxes;
    std::vector<shaders::ObstacleRecord> records;
    for (int k = 1; k <= substeps; ++k) {
        const double time = t + dt * double(k) / double(substeps);
        for (std::size_t o = 0; o < solids.size(); ++o) {
            poses[o] = solids[o].poseAt(time);
            records.push_back(obstacleRecord(solids[o], poses[o], mLattices));
        }
        boxes.push_back(displacementBoxes(solids, poses, grid));
    }
    mPoses.upload<shaders::ObstacleRecord>(records);

    shaders::SmokeDisplaceParams params{};
    params.dim = std::uint32_t(grid.dim);
    params.periodic = grid.periodicBits();
    for (int a = 0; a < 3; ++a) {
        params.cells[a] = std::uint32_t(grid.cells[a]);
        params.origin[a] = float(grid.origin[a]);
        params.spacing[a] = float(grid.spacing[a]);
    }
    params.obstacleCount = std::uint32_t(solids.size());
    params.dt = float(dt);
    const std::uint32_t maxGroups = mContext.properties().limits.maxComputeWorkGroupCount[0];
    params.maxGroups = maxGroups;
    // Bindings 0-11 of shaders/smoke_displace.comp, for each pair of fields.
    const auto buffersOf = [&](SmokePair pair) {
        const SmokePair other =
            state.fire() && pair == SmokePair::Smoke ? SmokePair::Fuel : SmokePair::Smoke;
        return std::array<const vulkan::DeviceBuffer*, 12>{
            &mPoses,  &mLattices.buffer(), &state.mask(),       &mCover,
            &mTarget, &state.fields(pair), &state.second(pair), &state.hat(),
            &mWork,   &mCovered,           &mReceivers,         &state.fields(other)};
    };
    const auto buffers = buffersOf(SmokePair::Smoke);
    const std::int64_t perDispatch = std::int64_t(maxGroups) * kWorkgroupSize;
    for (int k = 0; k < substeps; ++k) {
        if (++mStamp == kStampLimit) {
            // Every stamp used: clear the words, whose stale stamps would otherwise come back.
            sequence.fill(mCover, mCover.bytes(), 0u);
            sequence.fill(mTarget, mTarget.bytes(), 0u);
            mStamp = 1;
        }
        params.stamp = mStamp;
        params.firstRecord = std::uint32_t(std::size_t(k) * solids.size());
        sequence.fill(mWork, mWork.bytes(), 0u);
        for (const CellBox& box : boxes[std::size_t(k)]) {
            params.boxLines = std::uint32_t(box.cellCount() > 0 ? box.count[1] * box.count[2] : 0);
            for (int a = 0; a < 3; ++a) {
                // Onto the grid along periodic axes: the box's cells are then less than two
                // grid lengths from its start (the shader's wrapped()).
                params.boxFirst[a] = grid.wrap(a, box.first[a]);
                params.boxCount[a] = std::uint32_t(box.count[a]);
            }
            const std::int64_t invocations = params.boxLines;
            for (std::int64_t first = 0; first < invocations; first += perDispatch) {
                params.firstInvocation = std::uint32_t(first);
                const std::int64_t chunk = std::min(perDispatch, invocations - first);
                sequence.dispatch(mStages.with({SMOKE_DISPLACE_COVER, kinds}), buffers, params,
                                  std::uint32_t((chunk + kWorkgroupSize - 1) / kWorkgroupSize));
            }
        }
        // Bytes 0 and 16 of mWork: the push's and the gather's group counts.
        sequence.dispatch(mStages.with({SMOKE_DISPLACE_ARGS, kinds}), buffers, params, 1);
        sequence.dispatchIndirect(mStages.with({SMOKE_DISPLACE_PUSH, kinds}), buffers, params,
                                  mWork, 0);
        sequence.dispatch(mStages.with({SMOKE_DISPLACE_ARGS, kinds}), buffers, params, 1);
        sequence.dispatchIndirect(mStages.with({SMOKE_DISPLACE_GATHER, kinds}), buffers, params,
                                  mWork, 16);
        if (state.fire()) {
            // The fuel moves as the smoke did, to the targets the push chose (the lists and the
            // dispatch arguments stand): stashed, then gathered.
            const auto fuel = buffersOf(SmokePair::Fuel);
            sequence.dispatchIndirect(mStages.with({SMOKE_DISPLACE_STASH, kinds}), fuel, params,
                                      mWork, 0);
            sequence.dispatchIndirect(mStages.with({SMOKE_DISPLACE_GATHER, kinds}), fuel, params,
                                      mWork, 16);
        }
    }
}

}  // namespace modeflow::device
