#pragma once
/// @file MovingObstacle.h
/// A solid moving through the fluid on a key-framed path (`[[obstacle]]`, seed §6.3.5): where
/// it is, how fast it moves and what it covers. Both backends make the fluid's normal velocity
/// on the faces it covers match its own (ObstacleCorrection in engine/reference and
/// engine/device).

#include "engine/core/MacGrid.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/core/SceneSpec.h"

namespace modeflow {

struct MovingObstacle {
    ObstacleSpec spec;

    /// Centre at time t: linear between key frames, held before the first and after the last.
    Vec3 centreAt(double t) const;
    /// Velocity at time t (of the key-frame segment holding t; 0 outside the path's span).
    Vec3 velocityAt(double t) const;
    /// Whether the world point lies in the solid when its centre is `centre` (the grid's axes;
    /// along its periodic ones at the minimum-image offset, so a solid on the seam covers both
    /// ends).
    bool covers(const Vec3& point, const Vec3& centre, const MacGrid& grid) const;
};

}  // namespace modeflow
