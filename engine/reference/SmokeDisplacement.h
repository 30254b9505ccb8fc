#pragma once
/// @file SmokeDisplacement.h
/// Smoke pushed out of solids after each step's advection, in double precision: the CPU
/// reference of engine/device/SmokeDisplacement (the rule: engine/simulation/SmokeDisplacement.h).

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/SmokeFields.h"

namespace modeflow::reference {

class SmokeDisplacement {
public:
    /// `fluidMask`: one entry per cell of `smokeGrid`, non-zero inside Ω.
    /// @throw modeflow::Error when the mask has the wrong size.
    SmokeDisplacement(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask);

    /// Pushes the smoke that `solids` cover during the step [t, t + dt] out of them
    /// (displacementSubsteps substeps); nothing without solids.
    /// @throw modeflow::Error when the fields have the wrong size or the solids move too fast.
    void step(std::span<const MovingObstacle> solids, double t, double dt, SmokeFields& fields);

private:
    /// One substep: the solids where `poses` put them.
    void substep(std::span<const MovingObstacle> solids, std::span<const ObstaclePose> poses,
                 double dt, SmokeFields& fields);
    bool isCovered(std::int64_t cell) const { return mCoveredAt[std::size_t(cell)] == mStamp; }
    /// The cell `offset` from (x, y, z) (wrapped along periodic axes), or -1 off a walled one.
    std::int64_t neighbour(const std::array<int, 3>& at, const std::array<int, 3>& offset) const;

    MacGrid mGrid;
    std::vector<std::uint8_t> mFluid;
    /// The substep that last found each cell covered, by which solid, and the offset (index in
    /// pushOffsets) its smoke went along (-1: nowhere).
    std::vector<std::int64_t> mCoveredAt;
    std::vector<std::uint8_t> mCoverer;
    std::vector<std::int8_t> mTarget;
    std::int64_t mStamp = 0;
};

}  // namespace modeflow::reference
