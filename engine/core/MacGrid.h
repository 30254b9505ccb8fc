#pragma once
/// @file MacGrid.h
/// The regular grid of a scene seen as a MAC grid (precompute/README.md; engine/README.md): cells, and faces numbered as
/// the precompute's CubicalComplex numbers them, so the basis's face DOFs index straight into it:
/// faces grouped by normal axis (axis 0 first), inside a group x fastest, with n_a + 1 positions
/// along the normal axis a and n_b along the others. Cells are numbered x fastest.
///
/// A face value in a "face field" is the face-normal velocity (or force density) averaged over
/// the whole face: a flux divided by the full face area (the divergence-free fluxes stay
/// divergence-free on the full grid that way). Unused axes of a 2D grid have 1 cell and size 1.

#include <array>
#include <cstdint>

#include "engine/core/SceneSpec.h"

namespace modeflow {

struct MacGrid {
    int dim = 2;
    std::array<int, 3> cells{1, 1, 1};
    std::array<double, 3> origin{0.0, 0.0, 0.0};   ///< lower corner of the box
    std::array<double, 3> spacing{1.0, 1.0, 1.0};  ///< cell size per axis

    static MacGrid fromSpec(const GridSpec& grid);
    /// The same box with `scale` cells per cell along each used axis (the smoke grid).
    MacGrid refined(int scale) const;

    std::int64_t cellCount() const { return std::int64_t(cells[0]) * cells[1] * cells[2]; }
    std::int64_t cellIndex(int x, int y, int z) const {
        return (std::int64_t(z) * cells[1] + y) * cells[0] + x;
    }
    /// Position of cell (x, y, z)'s centre along `axis`.
    double cellCentre(int axis, int position) const { return origin[axis] + (position + 0.5) * spacing[axis]; }

    /// Positions of normal-`axis` faces along each axis.
    std::array<int, 3> faceExtent(int axis) const {
        std::array<int, 3> e = cells;
        e[axis] += 1;
        return e;
    }
    std::int64_t faceCount(int axis) const {
        const std::array<int, 3> e = faceExtent(axis);
        return std::int64_t(e[0]) * e[1] * e[2];
    }
    /// Number of the first normal-`axis` face.
    std::int64_t faceOffset(int axis) const {
        std::int64_t offset = 0;
        for (int a = 0; a < axis; ++a) offset += faceCount(a);
        return offset;
    }
    std::int64_t faceTotal() const { return faceOffset(dim); }
    /// The normal-`axis` face at lower corner (x, y, z): between cells x−1 and x along axis 0.
    std::int64_t faceIndex(int axis, int x, int y, int z) const {
        const std::array<int, 3> e = faceExtent(axis);
        return faceOffset(axis) + (std::int64_t(z) * e[1] + y) * e[0] + x;
    }
    /// Area of a whole normal-`axis` face (a length in 2D).
    double faceArea(int axis) const;
    double cellVolume() const { return spacing[0] * spacing[1] * spacing[2]; }
};

}  // namespace modeflow
