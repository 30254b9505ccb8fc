#pragma once
/// @file ObstacleRecords.h
/// An obstacle at an instant as the device kernels read it (shaders/ObstacleParams.h,
/// ObstacleShape.glsl), for ObstacleCorrection and SmokeDisplacement.

#include <cstdint>

#include "engine/simulation/MovingObstacle.h"
#include "shaders/ObstacleParams.h"

namespace modeflow::device {

/// `obstacle` where `pose` puts it, its lattice from `latticeStart` (ObstacleLattices::update).
shaders::ObstacleRecord obstacleRecord(const MovingObstacle& obstacle, const ObstaclePose& pose,
                                       std::uint32_t latticeStart);

}  // namespace modeflow::device
