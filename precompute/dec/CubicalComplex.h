#pragma once
/// @file CubicalComplex.h
/// The cubical cell complex of a regular grid in 2 or 3 dimensions (precompute/README.md).
///
/// A k-cell is identified by the set of axes it extends along (a bit mask with k bits) and the
/// integer position of its lower corner. Along an axis in the mask there are n_a positions, along
/// any other axis n_a + 1. Cells of one dimension are numbered type by type; faces ((n-1)-cells)
/// are ordered by their normal axis, so face type `a` has normal `a`. Within a type, x fastest:
/// index = offset(type) + (z·e_y + y)·e_x + x with e the type's extent.
///
/// Periodic axes (GridSpec::periodic): the complex wraps. Along a periodic axis every element
/// type has n_a positions 0 … n_a − 1, the plane at n_a being the plane at 0; the incidence
/// matrices wrap (the upper face of the last cell is the lower face of the first), and nothing
/// on that axis lies on the box boundary.
///
/// Open sides (GridSpec::open): their faces have one cell, inside the box; the cell beyond is
/// no element (its pressure is held at 0).

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "engine/core/SceneSpec.h"

namespace modeflow {

using Index3 = std::array<int, 3>;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, std::int64_t>;

/// One element of the complex: its axis mask and lower-corner position.
struct Element {
    unsigned axes = 0;
    Index3 pos{0, 0, 0};
};

class CubicalComplex {
public:
    explicit CubicalComplex(const GridSpec& grid);

    const GridSpec& grid() const { return mGrid; }
    int dim() const { return mGrid.dim; }

    /// Axis masks of the k-cells, in numbering order. For k = n-1 entry a is the face normal a.
    const std::vector<unsigned>& types(int k) const { return mTypes[k]; }
    /// Positions per axis for a type (1 along unused axes in 2D).
    Index3 extent(unsigned axes) const;
    std::int64_t countOfType(unsigned axes) const;
    std::int64_t count(int k) const { return mCounts[k]; }

    /// Global number of an element among the k-cells (k = popcount of its mask).
    std::int64_t index(const Element& e) const;
    Element element(int k, std::int64_t index) const;

    /// True when the element lies on a wall of the grid box: at position 0 or n_a along a
    /// non-periodic axis it does not extend along, on a side that is not open (an element on an
    /// open side and on no wall is inside the air).
    bool onWall(const Element& e) const;
    /// `position` along `axis` brought into 0 … n_a − 1 on a periodic axis (a neighbour across
    /// the seam); unchanged on other axes.
    int wrap(int axis, int position) const;

    /// Calls fn(face, cell) for every face normal to `axis` on the box's two sides along it
    /// (none along a periodic axis), `cell` the cell inside beside it.
    template <typename Fn>
    void forEachSideFace(int axis, Fn&& fn) const {
        if (mGrid.isPeriodic(axis)) return;
        const int n = mGrid.dim;
        const unsigned faceAxes = ((1u << n) - 1) & ~(1u << axis);
        const Index3 extent = this->extent(faceAxes);
        for (const int side : {0, mGrid.resolution[axis]}) {
            Index3 first{0, 0, 0}, end = extent;  // the side's plane of faces
            first[axis] = side;
            end[axis] = side + 1;
            for (int k = first[2]; k < end[2]; ++k)
                for (int j = first[1]; j < end[1]; ++j)
                    for (int i = first[0]; i < end[0]; ++i) {
                        const Element face{faceAxes, {i, j, k}};
                        Element cell{(1u << n) - 1, face.pos};
                        if (side != 0) --cell.pos[axis];
                        fn(face, cell);
                    }
        }
    }

    /// Signed incidence d_k from k-cells to (k+1)-cells, d_{k+1} d_k = 0. Faces are oriented so a
    /// positive value is a flux along +normal: (d_{n-1} Ψ)_cell = Σ outflow through its faces.
    SparseMatrix incidence(int k) const;

private:
    GridSpec mGrid;
    std::array<std::vector<unsigned>, 4> mTypes;
    std::array<std::int64_t, 4> mCounts{};
    std::array<std::int64_t, 8> mTypeOffset{};  ///< by mask
};

inline int popcount(unsigned m) {
    return __builtin_popcount(m);
}

}  // namespace modeflow
