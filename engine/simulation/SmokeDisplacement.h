#pragma once
/// @file SmokeDisplacement.h
/// Smoke that solids displace: what both backends' displacement stage shares (CPU reference
/// engine/reference/SmokeDisplacement.h, device engine/device/SmokeDisplacement.h).
///
/// After each step's advection and emitters, no smoke cell whose centre a solid (an
/// `[[obstacle]]`, not a jet's region) covers keeps smoke: the step is cut into substeps in
/// which no solid's surface moves more than half a smoke cell, and at the end of each substep a
/// covered fluid cell hands its density and temperature to the uncovered fluid cell beside it
/// (26 neighbours in 3D, 8 in 2D) that lies most nearly along the solid's material velocity
/// there (v + ω × r; outward from the solid's centre where the solid is still), then holds 0.
/// The smoke in front of a moving solid is pushed ahead of it, none is carried through a solid
/// one cell thick, and the smoke is conserved — except where a covered cell has no uncovered
/// fluid neighbour (a solid that appears over smoke, or is placed where the smoke already is):
/// that smoke is removed. Each receiving cell gathers from its neighbours in pushOffsets order,
/// so the sums do not depend on the order cells are visited: resumed runs stay bit for bit.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/simulation/MovingObstacle.h"

namespace modeflow {

/// The most substeps one step may take: a solid's surface then moves up to 32 smoke cells a step.
inline constexpr int maxDisplacementSubsteps = 64;

/// Substeps of the step [t, t + dt] (at least 1): the solids' surfaces move at most half of the
/// smoke grid's smallest spacing in each.
/// @throw modeflow::Error when that takes more than maxDisplacementSubsteps.
int displacementSubsteps(std::span<const MovingObstacle> solids, double t, double dt,
                         const MacGrid& smokeGrid);

/// Refuses solids whose key frames ever move their surface faster than maxDisplacementSubsteps
/// substeps of one step can follow, naming the first and its speed.
/// @throw modeflow::Error
void requireDisplaceableMotion(std::span<const MovingObstacle> solids, double dt,
                               const MacGrid& smokeGrid);

/// Smoke cells in a box: `first` may lie outside the grid along periodic axes (positions wrap),
/// `count` is at most the grid's cells along each axis. Empty: a count of 0.
struct CellBox {
    std::array<int, 3> first{0, 0, 0};
    std::array<int, 3> count{0, 0, 0};
    std::int64_t cellCount() const { return std::int64_t(count[0]) * count[1] * count[2]; }
};

/// The cells of `grid` the solids at `poses` may cover — each solid's shape box in its own frame
/// (a mesh's lattice), turned, within its reach — with one cell around them (where their smoke
/// goes; on the basis grid, the faces the obstacle mismatch walks).
CellBox displacementBox(std::span<const MovingObstacle> solids, std::span<const ObstaclePose> poses,
                        const MacGrid& grid);

/// Whether every cell of `inner` lies in `outer` (along a periodic axis either may go round).
bool boxContains(const CellBox& outer, const CellBox& inner, const MacGrid& grid);

/// displacementBox of the solids at t, t + dt, …, t + (steps − 1)·dt: a box that holds each of
/// those steps' boxes, for work recorded once and run while the solids stay inside it.
CellBox sweptDisplacementBox(std::span<const MovingObstacle> solids, double t, double dt, int steps,
                             const MacGrid& grid);

/// The cells to cover as boxes: displacementBox of all the solids, or one box each where those
/// hold fewer cells together (solids far apart).
std::vector<CellBox> displacementBoxes(std::span<const MovingObstacle> solids,
                                       std::span<const ObstaclePose> poses,
                                       const MacGrid& smokeGrid);

/// The neighbour offsets smoke may be pushed along, in the order ties are broken: 26 in 3D, 8
/// in 2D (z = 0).
std::span<const std::array<int, 3>> pushOffsets(int dim);

/// A push must beat the best before it by this much in cos(offset, direction): symmetric ties
/// fall to the earlier offset on both backends whatever their rounding.
inline constexpr double pushTieMargin = 1e-4;

/// Where smoke covered at `point` by `solid` at `pose` is pushed, in smoke-cell units: the
/// solid's material velocity there, or outward from its centre where that moves less than a
/// thousandth of a cell in `dt` (0 at the centre itself: the first free offset takes it).
Vec3 pushDirection(const MovingObstacle& solid, const ObstaclePose& pose, const Vec3& point,
                   double dt, const MacGrid& smokeGrid);

}  // namespace modeflow
