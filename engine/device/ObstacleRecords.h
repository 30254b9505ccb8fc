#pragma once
/// @file ObstacleRecords.h
/// An obstacle at an instant as the device kernels read it (shaders/ObstacleParams.h,
/// ObstacleShape.glsl), for ObstacleCorrection and SmokeDisplacement.

#include "engine/device/ObstacleLattices.h"
#include "engine/simulation/MovingObstacle.h"
#include "shaders/ObstacleParams.h"

namespace modeflow::device {

/// `obstacle` where `pose` puts it, its shape then (a mesh's) from `lattices`.
shaders::ObstacleRecord obstacleRecord(const MovingObstacle& obstacle, const ObstaclePose& pose,
                                       const ObstacleLattices& lattices);

}  // namespace modeflow::device
