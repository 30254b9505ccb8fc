#pragma once
/// @file ObstacleCorrection.h
/// Moving obstacles on the device (seed §6.3.5; CPU reference engine/simulation/MovingObstacle.h):
/// records mismatch → projection → v −= Δv, where the mismatch is the fluid's face velocity
/// minus the obstacle's normal velocity on the DOF faces an obstacle covers, found among the faces
/// of the box of cells within the regions' reach.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/device/ForceProjection.h"
#include "engine/device/ObstacleLattices.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/SmokeDisplacement.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class ModeBuffer;
class SeparableTransformKernels;

class ObstacleCorrection {
public:
    /// For the DOFs, grid and modes of `cache`.
    /// @throw modeflow::Error if a creation call fails.
    ObstacleCorrection(const vulkan::VulkanContext& context, const BasisCache& cache);

    /// The obstacles where they are at time t. Between submissions only. Mesh obstacles' level
    /// sets are uploaded when they differ from the last call's.
    /// @throw modeflow::Error for more than maxVelocityRegions, or a mesh obstacle without its
    ///        level set.
    void setObstacles(std::span<const MovingObstacle> obstacles, double t);

    /// The cells the obstacles set may cover, with one around them (displacementBox: their
    /// faces are those the mismatch reads; along periodic axes the box may wrap).
    CellBox cellBox() const { return mBox; }
    /// The cells whose faces the recordings walk: cellBox() as setObstacles leaves it, or a box
    /// holding it (widenRecordBox). Faces the obstacles do not cover add zeros, so a recording
    /// with a larger box gives the same correction while the obstacles stay inside it.
    CellBox recordBox() const { return mRecordBox; }
    /// Records from now on walk `box`, which must hold cellBox() (sweptDisplacementBox).
    /// @throw modeflow::Error when it does not.
    void widenRecordBox(const CellBox& box);
    /// What a recording holds besides the buffers' contents: the obstacles' count, their kinds
    /// (kernel variants) and the level sets' buffer.
    std::uint32_t obstacleCount() const { return mObstacleCount; }
    std::uint32_t kinds() const { return mKinds; }
    std::uint64_t latticeGeneration() const { return mLattices.generation(); }
    const MacGrid& grid() const { return mGrid; }

    /// Records v −= Ψᵀ⋆(mismatch of `faceField`) with the basis in `modes`; nothing without
    /// obstacles.
    void record(vulkan::CommandSequence& sequence, const ModeBuffer& modes,
                const vulkan::DeviceBuffer& faceField, const vulkan::DeviceBuffer& v) const;
    /// The same with a closed-form basis's transforms.
    void record(vulkan::CommandSequence& sequence, const SeparableTransformKernels& transforms,
                const vulkan::DeviceBuffer& faceField, const vulkan::DeviceBuffer& v) const;

private:
    /// The mismatch, then `project` (mismatch → correction), then v −= correction.
    template <typename Project>
    void recordWith(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& faceField,
                    const vulkan::DeviceBuffer& v, Project&& project) const;

    const vulkan::VulkanContext& mContext;
    MacGrid mGrid;
    std::uint32_t mModeCount = 0;
    std::uint32_t mObstacleCount = 0;
    std::uint32_t mKinds = 0;  ///< solidKinds of the obstacles now
    CellBox mBox;              ///< cellBox(), set by setObstacles
    CellBox mRecordBox;        ///< recordBox()

    vulkan::DeviceBuffer mObstacles;
    vulkan::DeviceBuffer mDofOfFace;  ///< per grid face its DOF, OBSTACLE_NO_DOF for none
    vulkan::DeviceBuffer mMismatch;   ///< per DOF (DOF order)
    vulkan::DeviceBuffer mCorrection;
    ObstacleLattices mLattices;
    ForceProjectionKernel mProjection;
    vulkan::KernelVariants mMismatchKernels;  ///< by solid kinds
    vulkan::ComputeKernel mCorrectKernel;
};

}  // namespace modeflow::device
