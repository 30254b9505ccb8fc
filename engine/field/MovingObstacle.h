#pragma once
/// @file MovingObstacle.h
/// Solids moving through the fluid (seed §6.3.5, DESIGN §3): rather than extra boundary bases,
/// the mismatch between the fluid's and the obstacle's normal velocity on the faces the obstacle
/// covers is projected on the velocity basis and subtracted from v, leaving a low-frequency
/// field that roughly satisfies the moving boundary condition. This is the CPU reference of the
/// device's obstacle kernel (engine/kernels/ObstacleCorrection).

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/field/MacGrid.h"
#include "engine/field/RuntimeLimits.h"
#include "engine/format/BasisCache.h"
#include "precompute/scene/SceneSpec.h"

namespace modeflow {

struct MovingObstacle {
    ObstacleSpec spec;

    /// Centre at time t: linear between key frames, held before the first and after the last.
    Vec3 centreAt(double t) const;
    /// Velocity at time t (of the key-frame segment holding t; 0 outside the path's span).
    Vec3 velocityAt(double t) const;
    /// Whether the world point lies in the solid when its centre is `centre` (first `dim` axes).
    bool covers(const Vec3& point, const Vec3& centre, int dim) const;
};

/// A face field of the cache's grid: on every DOF face whose centre an obstacle covers at time
/// t, the fluid's face velocity minus the obstacle's velocity along the face normal; 0 elsewhere.
/// @throw modeflow::Error when `faceField` is not one value per face of the grid.
std::vector<double> obstacleMismatch(const BasisCache& cache, std::span<const double> faceField,
                                     std::span<const MovingObstacle> obstacles, double t);

/// The correction Δv (projectFaceField of the mismatch) that `v -= Δv` applies.
Eigen::VectorXd obstacleCorrection(const BasisCache& cache, std::span<const double> faceField,
                                   std::span<const MovingObstacle> obstacles, double t);

}  // namespace modeflow
