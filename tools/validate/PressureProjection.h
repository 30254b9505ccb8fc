#pragma once
/// @file PressureProjection.h
/// The full grid's answer to a force, with no basis at all: the L²-orthogonal projection of a
/// face field onto discretely divergence-free MAC fields of a closed box (no flux through its
/// walls), g − Gp with D(g − Gp) = 0, by conjugate gradients on the pressure. With every
/// divergence-free mode of the grid kept, one step of the reduced chain under a force density g
/// moves the fluid by exactly dt·P(g) (tests/engine/BuoyancyScaleTest); with N modes by dt·P_N(g).

#include <span>
#include <vector>

#include "engine/core/MacGrid.h"

namespace modeflow::validate {

/// P(g) for a face field g of `grid` (MacGrid numbering, box faces 0), to a relative residual of
/// 1e-12. Walled axes only.
/// @throw modeflow::Error for a periodic axis or a field of the wrong size.
std::vector<double> pressureProjection(const MacGrid& grid, std::span<const double> g);

}  // namespace modeflow::validate
