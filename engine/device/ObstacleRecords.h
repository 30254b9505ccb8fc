#pragma once
/// @file ObstacleRecords.h
/// An obstacle at an instant as the device kernels read it (shaders/ObstacleParams.h,
/// ObstacleShape.glsl), for ObstacleCorrection and SmokeDisplacement.

#include <cstdint>
#include <span>

#include "engine/device/ObstacleLattices.h"
#include "engine/simulation/MovingObstacle.h"
#include "shaders/ObstacleParams.h"

namespace modeflow::device {

/// The kinds of solid `solids` hold, the last specialization constant of the kernels that read
/// their records (shaders/ObstacleShape.glsl), so the code of absent kinds folds away: bit
/// 1 << OBSTACLE_<shape> for each shape present, SOLID_KIND_DEFORMING for a mesh sequence.
/// Lavapipe runs both sides of every branch whichever lanes take it: a scene of rigid meshes would
/// otherwise pay for the ball, box and capsule tests and a deforming mesh's velocity samples at
/// every point. A run's solids keep their kinds: it compiles one variant.
std::uint32_t solidKinds(std::span<const MovingObstacle> solids);

/// `obstacle` where `pose` puts it, its shape then (a mesh's) from `lattices`.
shaders::ObstacleRecord obstacleRecord(const MovingObstacle& obstacle, const ObstaclePose& pose,
                                       const ObstacleLattices& lattices);

}  // namespace modeflow::device
