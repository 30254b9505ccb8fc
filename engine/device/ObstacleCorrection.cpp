#include "engine/device/ObstacleCorrection.h"

#include <algorithm>
#include <array>
// The generated headers use uint32_t without including <cstdint>.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/DofFaces.h"
#include "engine/device/ObstacleRecords.h"
#include "engine/device/SeparableTransform.h"
#include "engine/vulkan/CommandSequence.h"
#include "shaders/ObstacleParams.h"
#include "shaders/modal_correct.spv.h"
#include "shaders/obstacle_mismatch.spv.h"

namespace modeflow::device {
namespace {

vulkan::DeviceBuffer zeros(const vulkan::VulkanContext& context, std::size_t count,
                           const char* name) {
    return vulkan::DeviceBuffer::fromValues<float>(context, std::vector<float>(count, 0.0f), name);
}

}  // namespace

ObstacleCorrection::ObstacleCorrection(const vulkan::VulkanContext& context,
                                       const BasisCache& cache)
    : mContext(context),
      mGrid(MacGrid::fromSpec(cache.grid)),
      mDofCount(std::uint32_t(cache.faces.size())),
      mModeCount(std::uint32_t(cache.velocity.eigenvalues.size())),
      mFaces(uploadDofFaces(context, cache)),
      mObstacles(context, maxVelocityRegions * sizeof(shaders::ObstacleRecord), "obstacles"),
      mMismatch(zeros(context, std::size_t(mGrid.faceTotal()), "obstacle mismatch")),
      mCorrection(zeros(context, paddedSize(int(mModeCount)), "obstacle correction")),
      mLattices(context),
      mProjection(context, cache, FaceQuantity::FaceField),
      mMismatchKernel(context, {"obstacle_mismatch", obstacle_mismatch_spv, 5,
                                sizeof(shaders::ObstacleMismatchParams), 64}),
      mCorrectKernel(context, {"modal_correct", modal_correct_spv, 2,
                               sizeof(shaders::ModalCorrectParams), 64}) {}

void ObstacleCorrection::setObstacles(std::span<const MovingObstacle> obstacles, double t) {
    if (obstacles.size() > std::size_t(maxVelocityRegions))
        throw Error(std::to_string(obstacles.size()) +
                    " obstacles and driving sources; the runtime takes at most " +
                    std::to_string(maxVelocityRegions));
    requireLevelSets(obstacles);
    mLattices.update(obstacles);
    std::vector<shaders::ObstacleRecord> records;
    for (const MovingObstacle& obstacle : obstacles)
        records.push_back(obstacleRecord(obstacle, obstacle.poseAt(t), mLattices));
    if (!records.empty()) mObstacles.upload<shaders::ObstacleRecord>(records);
    mObstacleCount = std::uint32_t(records.size());
}

template <typename Project>
void ObstacleCorrection::recordWith(vulkan::CommandSequence& sequence,
                                    const vulkan::DeviceBuffer& faceField,
                                    const vulkan::DeviceBuffer& v, Project&& project) const {
    if (mObstacleCount == 0) return;
    requireWords("obstacle_mismatch", faceField, std::uint64_t(mGrid.faceTotal()));
    requireWords("modal_correct", v, mModeCount);
    shaders::ObstacleMismatchParams params{};
    params.dofCount = mDofCount;
    params.obstacleCount = mObstacleCount;
    params.faceStart1 = std::uint32_t(mGrid.faceOffset(1));
    params.faceStart2 = std::uint32_t(mGrid.faceOffset(2));
    params.dim = std::uint32_t(mGrid.dim);
    params.periodic = mGrid.periodicBits();
    for (int a = 0; a < 3; ++a) {
        params.cells[a] = std::uint32_t(mGrid.cells[a]);
        params.origin[a] = float(mGrid.origin[a]);
        params.spacing[a] = float(mGrid.spacing[a]);
    }
    const std::array<const vulkan::DeviceBuffer*, 5> mismatchBuffers{
        &mFaces, &faceField, &mObstacles, &mMismatch, &mLattices.buffer()};
    sequence.dispatch(mMismatchKernel, mismatchBuffers, params, groupsFor(mContext, mDofCount, 64));
    project();
    const std::array<const vulkan::DeviceBuffer*, 2> correctBuffers{&v, &mCorrection};
    sequence.dispatch(mCorrectKernel, correctBuffers,
                      shaders::ModalCorrectParams{mModeCount, 0, 0, 0}, (mModeCount + 63) / 64);
}

void ObstacleCorrection::record(vulkan::CommandSequence& sequence, const ModeBuffer& modes,
                                const vulkan::DeviceBuffer& faceField,
                                const vulkan::DeviceBuffer& v) const {
    recordWith(sequence, faceField, v,
               [&] { mProjection.record(sequence, modes, mMismatch, mCorrection); });
}

void ObstacleCorrection::record(vulkan::CommandSequence& sequence,
                                const SeparableTransformKernels& transforms,
                                const vulkan::DeviceBuffer& faceField,
                                const vulkan::DeviceBuffer& v) const {
    recordWith(sequence, faceField, v,
               [&] { transforms.recordFaceFieldProjection(sequence, mMismatch, mCorrection); });
}

}  // namespace modeflow::device
