#pragma once
/// @file ObstacleCorrection.h
/// Moving obstacles on the CPU (seed §6.3.5): the mismatch between the fluid's and the
/// obstacle's normal velocity on the faces an obstacle covers, projected on the basis and
/// subtracted from v. The reference of engine/device/ObstacleCorrection.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/basis/VelocityBasis.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/MovingObstacle.h"

namespace modeflow::reference {

/// A face field of the cache's grid: on every DOF face whose centre an obstacle covers at time
/// t, the fluid's face velocity minus the obstacle's velocity along the face normal; 0 elsewhere.
/// @throw modeflow::Error when `faceField` is not one value per face of the grid.
std::vector<double> obstacleMismatch(const BasisCache& cache, std::span<const double> faceField,
                                     std::span<const MovingObstacle> obstacles, double t);

/// The correction Δv (projectFaceField of the mismatch) that `v -= Δv` applies.
Eigen::VectorXd obstacleCorrection(const VelocityBasis& basis, std::span<const double> faceField,
                                   std::span<const MovingObstacle> obstacles, double t);
Eigen::VectorXd obstacleCorrection(const BasisCache& cache, std::span<const double> faceField,
                                   std::span<const MovingObstacle> obstacles, double t);

}  // namespace modeflow::reference
