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
#include "engine/vulkan/VulkanContext.h"
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
      mModeCount(std::uint32_t(cache.velocity.eigenvalues.size())),
      mObstacles(context, maxVelocityRegions * sizeof(shaders::ObstacleRecord), "obstacles"),
      mDofOfFace(uploadFaceDofs(context, cache, OBSTACLE_NO_DOF)),
      mMismatch(zeros(context, cache.faces.size(), "obstacle mismatch")),
      mCorrection(zeros(context, paddedSize(int(mModeCount)), "obstacle correction")),
      mLattices(context),
      mProjection(context, cache, FaceQuantity::FaceField,
                  ForceProjectionOptions{.dofOrder = true}),
      // Records as texels (binding 1); the velocity, lattices and DOFs as values (0, 3, 4):
      // shaders/ObstacleShape.glsl.
      mMismatchKernels(context, {"obstacle_mismatch",
                                 obstacle_mismatch_spv,
                                 5,
                                 sizeof(shaders::ObstacleMismatchParams),
                                 64,
                                 {},
                                 {1},
                                 {},
                                 {0, 3, 4}}),
      mCorrectKernel(context, {"modal_correct", modal_correct_spv, 2,
                               sizeof(shaders::ModalCorrectParams), 64}) {}

void ObstacleCorrection::setObstacles(std::span<const MovingObstacle> obstacles, double t) {
    if (obstacles.size() > std::size_t(maxVelocityRegions))
        throw Error(std::to_string(obstacles.size()) +
                    " obstacles and driving sources; the runtime takes at most " +
                    std::to_string(maxVelocityRegions));
    requireLevelSets(obstacles);
    mLattices.update(obstacles);
    std::vector<ObstaclePose> poses;
    std::vector<shaders::ObstacleRecord> records;
    for (const MovingObstacle& obstacle : obstacles) {
        poses.push_back(obstacle.poseAt(t));
        records.push_back(obstacleRecord(obstacle, poses.back(), mLattices));
    }
    if (!records.empty()) mObstacles.upload<shaders::ObstacleRecord>(records);
    mObstacleCount = std::uint32_t(records.size());
    mKinds = solidKinds(obstacles);
    // The cells the regions may cover: each one's shape box turned, within its reach (a
    // torus's flat box, not its reach's ball, bounds the faces the mismatch walks).
    mBox = displacementBox(obstacles, poses, mGrid);
    mRecordBox = mBox;
}

void ObstacleCorrection::widenRecordBox(const CellBox& box) {
    if (!boxContains(box, mBox, mGrid))
        throw Error("obstacle correction: the recorded box does not hold the obstacles' cells");
    mRecordBox = box;
}

template <typename Project>
void ObstacleCorrection::recordWith(vulkan::CommandSequence& sequence,
                                    const vulkan::DeviceBuffer& faceField,
                                    const vulkan::DeviceBuffer& v, Project&& project) const {
    if (mObstacleCount == 0) return;
    requireWords("obstacle_mismatch", faceField, std::uint64_t(mGrid.faceTotal()));
    requireWords("modal_correct", v, mModeCount);
    shaders::ObstacleMismatchParams params{};
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
    // The box's faces per normal axis: one more position along the axis than cells, as many as
    // the axis has along a periodic axis the box goes round; their lines along x.
    std::uint64_t lines = 0;  // an invocation each
    for (int axis = 0; axis < 3; ++axis) {
        for (int b = 0; b < 3; ++b) {
            int count = mRecordBox.count[b];
            if (b == axis)
                count = mGrid.periodic[b] ? std::min(count + 1, mGrid.cells[b]) : count + 1;
            params.boxCount[3 * axis + b] = std::uint32_t(count);
        }
        params.boxLines[axis] = axis < mGrid.dim && params.boxCount[3 * axis] > 0
                                    ? params.boxCount[3 * axis + 1] * params.boxCount[3 * axis + 2]
                                    : 0u;
        lines += params.boxLines[axis];
        // Onto the grid along a periodic axis (the shader then wraps by one length at most).
        params.boxFirst[axis] = mGrid.wrap(axis, mRecordBox.first[axis]);
    }
    // The DOFs the box leaves out hold 0.
    sequence.fill(mMismatch, mMismatch.bytes(), 0u);
    const std::array<const vulkan::DeviceBuffer*, 5> mismatchBuffers{
        &faceField, &mObstacles, &mMismatch, &mLattices.buffer(), &mDofOfFace};
    const std::uint64_t perDispatch =
        std::uint64_t(mContext.properties().limits.maxComputeWorkGroupCount[0]) * 64;
    for (std::uint64_t first = 0; first < lines; first += perDispatch) {
        params.first = std::uint32_t(first);
        sequence.dispatch(mMismatchKernels.with({mKinds}), mismatchBuffers, params,
                          std::uint32_t((std::min(perDispatch, lines - first) + 63) / 64));
    }
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
    // The mismatch is 0 off the box's faces: the passes take the box's lines alone.
    const CellBox box = recordBox();
    recordWith(sequence, faceField, v, [&] {
        transforms.recordFaceFieldProjection(sequence, mMismatch, mCorrection, &box);
    });
}

}  // namespace modeflow::device
