#pragma once
/// @file MovingObstacle.h
/// A solid moving through the fluid on key frames (`[[obstacle]]`, seed §6.3.5): where it is,
/// how it is turned, how fast each of its points moves and what it covers. Both backends make
/// the fluid's normal velocity on the faces it covers match its own (ObstacleCorrection in
/// engine/reference and engine/device).

#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "engine/core/MacGrid.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/core/SceneSpec.h"
#include "engine/simulation/SolidLevelSet.h"

namespace modeflow {

/// An obstacle at one instant.
struct ObstaclePose {
    Vec3 centre{0.0, 0.0, 0.0};
    Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  ///< its shape's frame → world
    Vec3 velocity{0.0, 0.0, 0.0};                               ///< of its centre
    Vec3 angularVelocity{0.0, 0.0, 0.0};                        ///< rad/s, world frame
    /// A mesh obstacle's shape then (a deforming one's file at that time); null: levelSet.
    const SolidLevelSet* shape = nullptr;
};

struct MovingObstacle {
    MovingObstacle() = default;
    MovingObstacle(ObstacleSpec spec, std::shared_ptr<const SolidLevelSet> levelSet = nullptr)
        : spec(std::move(spec)), levelSet(std::move(levelSet)) {}

    ObstacleSpec spec;
    /// A mesh obstacle's shape in its own frame (mesh units; tools/compose/MeshSolids.h
    /// builds it from spec.meshFile); null for the other shapes.
    std::shared_ptr<const SolidLevelSet> levelSet;
    /// A deforming mesh obstacle's level sets, file by file (spec.sequenceRate files per unit
    /// time; the first is levelSet), each holding its material's velocity; empty: rigid.
    std::vector<std::shared_ptr<const SolidLevelSet>> sequence;
    /// A region that drives the air rather than a solid (a [[source]] with `velocity`): its
    /// material moves at this velocity wherever its path puts it, and it does not spin.
    std::optional<Vec3> drive;

    /// Centre at time t: linear between key frames, held before the first and after the last.
    Vec3 centreAt(double t) const;
    /// Velocity at time t (of the key-frame segment holding t; 0 outside the path's span).
    Vec3 velocityAt(double t) const;
    /// Orientation at time t: between two rotation key frames about the same axis the angle moves
    /// linearly (so 0° to 720° turns twice), between others the orientations are slerped; held
    /// before the first key frame and after the last.
    Eigen::Matrix3d orientationAt(double t) const;
    /// Angular velocity at time t (of the rotation segment holding t; 0 outside their span).
    Vec3 angularVelocityAt(double t) const;
    /// Its mesh's shape at time t: file floor(t · rate) + 1 of a sequence (the first before
    /// t = 0, the last after the sequence ends), else levelSet.
    const SolidLevelSet* shapeAt(double t) const;
    ObstaclePose poseAt(double t) const;

    /// Whether the world point lies in the solid at `pose` (the grid's axes; along its periodic
    /// ones at the minimum-image offset, so a solid on the seam covers both ends). A mesh
    /// obstacle samples its level set at Rᵀ(x − c) / scale.
    bool covers(const Vec3& point, const ObstaclePose& pose, const MacGrid& grid) const;
    /// How far from its centre the solid reaches: no point farther is covered (spec and level
    /// set; a mesh's is its level set's radius, or its lattice's farthest corner).
    double reach() const;
    /// An upper bound of the speed of any point of its surface during [t0, t1]: the fastest
    /// path segment overlapping it plus the fastest rotation segment's |ω| × reach(), plus a
    /// deforming mesh's fastest material.
    double surfaceSpeedBound(double t0, double t1) const;
    /// The velocity of the solid's material at a world point: v + ω × r, with r from the centre
    /// at the minimum-image offset, plus a deforming mesh's own velocity there (turned and
    /// scaled into the world).
    Vec3 velocityOf(const Vec3& point, const ObstaclePose& pose, const MacGrid& grid) const;
};

/// Refuses a mesh obstacle without its level set (a caller that skipped obstacleSolids).
/// @throw modeflow::Error naming the obstacle and its file.
void requireLevelSets(std::span<const MovingObstacle> obstacles);

}  // namespace modeflow
