#pragma once
/// @file MacSampling.h
/// Trilinear sampling on a MacGrid (engine/README.md): the staggered (MAC) rule for a face field,
/// each velocity component interpolated from its own grid of face centres, and the cell-centred
/// rule for a cell field. 2D grids (cells[2] = 1) go through the same code: a one-cell axis has a
/// one-point stencil.
///
/// Points are given in *grid units*: (world − origin) / spacing per axis, so cell (i, j, k)
/// spans [i, i+1) × [j, j+1) × [k, k+1) and its centre is (i+½, j+½, k+½). Working in grid
/// units keeps cell centres exact in float32 as well, which lets the device kernels and this
/// reference pick the same stencils (worldToGrid() converts).
///
/// Outside the box (and between the last face or cell centre and the wall) every stencil is
/// clamped to the box: a cell field and a velocity's tangential components keep their nearest
/// value (constant extrapolation, the free-slip picture), while the normal component falls
/// linearly to zero at the wall, because the walls of the box carry zero normal velocity: the
/// wall faces (positions 0 and n along their normal) read as 0 whatever the field stores there.
/// A point with a non-finite coordinate (a diverged run) has an empty stencil and samples as 0.
///
/// Along a periodic axis nothing is clamped: stencils wrap across the seam (the last cell centre
/// or face interpolates with the first), so a point anywhere samples the field's periodic
/// continuation, continuous across the seam.

#include <array>
#include <cstdint>
#include <span>

#include "engine/core/MacGrid.h"

namespace modeflow {

/// (world − origin) / spacing per axis (unused 2D axis: its value as is, since spacing is 1).
Vec3 worldToGrid(const MacGrid& grid, const Vec3& world);

/// The trilinear stencil of a cell-centred field at a point: up to 8 distinct cells (4 in 2D)
/// with weights summing to 1. Cells whose weight is 0 (the point on a stencil plane) are still
/// listed, so min/max over the stencil do not depend on which side of the plane round-off put
/// the point.
struct CellStencil {
    std::array<std::int64_t, 8> cell{};  ///< MacGrid::cellIndex of each corner
    std::array<double, 8> weight{};
    int count = 0;
};

/// The cell-centred stencil at `gridPoint` (grid units), clamped to the box.
CellStencil cellStencil(const MacGrid& grid, const Vec3& gridPoint);

/// Cell-centred trilinear value of `field` (one value per cell, cellIndex order) at a world point.
double sampleCells(const MacGrid& grid, std::span<const double> field, const Vec3& world);

/// The face-normal velocity component along `axis` at `gridPoint` (grid units), interpolated
/// from the normal-`axis` faces of `faces` (a face field, MacGrid::faceIndex order). 0 for the
/// unused axis of a 2D grid.
template <typename T>
double sampleFaceComponent(const MacGrid& grid, std::span<const T> faces, int axis,
                           const Vec3& gridPoint);

/// All components at `gridPoint` (grid units), in world units per unit time.
template <typename T>
Vec3 sampleVelocityGrid(const MacGrid& grid, std::span<const T> faces, const Vec3& gridPoint);

/// All components at a world point.
template <typename T>
Vec3 sampleVelocity(const MacGrid& grid, std::span<const T> faces, const Vec3& world) {
    return sampleVelocityGrid(grid, faces, worldToGrid(grid, world));
}

/// @throw modeflow::Error naming `what` when `faces` is not one value per face of `grid`.
void requireFaceField(const MacGrid& grid, std::size_t size, const char* what);

}  // namespace modeflow
