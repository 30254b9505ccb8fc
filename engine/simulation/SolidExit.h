#pragma once
/// @file SolidExit.h
/// Where a point inside a solid leaves it, for particles pushed out of obstacles (both
/// backends; the device's twin is solidExit in shaders/ObstacleShape.glsl): the nearest point of
/// a ball's, box's or capsule's surface, and for a mesh the point its level set's gradient leads
/// to (Newton steps on the depth, a few at most; the gradient the trilinear depth's own in the
/// lattice cell, from the same eight samples), each then `margin` further out along the outward
/// normal, so the solid no longer covers it.

#include <optional>

#include "engine/core/MacGrid.h"
#include "engine/simulation/MovingObstacle.h"

namespace modeflow {

/// The Newton steps a mesh's exit takes at most.
inline constexpr int kMeshExitSteps = 4;

struct SolidExit {
    Vec3 point;   ///< world (the same periodic image as the point given)
    Vec3 normal;  ///< outward, unit length, world
};

/// None when `solid` at `pose` does not cover `point` (MovingObstacle::covers).
std::optional<SolidExit> solidExit(const MovingObstacle& solid, const Vec3& point,
                                   const ObstaclePose& pose, const MacGrid& grid, double margin);

}  // namespace modeflow
