#pragma once
/// @file MacGrid.h
/// The regular grid of a scene seen as a MAC grid (precompute/README.md; engine/README.md): cells,
/// and faces numbered as the precompute's CubicalComplex numbers them, so the basis's face DOFs
/// index straight into it: faces grouped by normal axis (axis 0 first), inside a group x fastest,
/// with n_a + 1 positions along the normal axis a and n_b along the others. Cells are numbered x
/// fastest.
///
/// Periodic axes (GridSpec::periodic) wrap: the box's two ends along them are one plane, so a
/// periodic normal axis has n_a face positions (the face at n_a is the face at 0), no wall, and
/// positions and offsets along it are taken modulo the box's length (wrap, minimumImage).
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
    /// Per axis: the box wraps (at least 2 cells along it).
    std::array<bool, 3> periodic{false, false, false};
    /// Per axis: the box's two sides across it let the air through (a wind blows along it,
    /// engine/simulation/WindTransport.h): the faces there are no walls, and sampling reads the
    /// velocity they carry.
    std::array<bool, 3> flowThrough{false, false, false};
    /// Per side, 2·axis + (0 low, 1 high): the side is open (GridSpec::open): its faces are
    /// degrees of freedom of the basis, no walls, and the smoke's ghost cells beyond it hold
    /// clean air.
    std::array<bool, 6> open{false, false, false, false, false, false};

    static MacGrid fromSpec(const GridSpec& grid);
    /// The same box with `scale` cells per cell along each used axis (the smoke grid).
    MacGrid refined(int scale) const;

    std::int64_t cellCount() const { return std::int64_t(cells[0]) * cells[1] * cells[2]; }
    std::int64_t cellIndex(int x, int y, int z) const {
        return (std::int64_t(z) * cells[1] + y) * cells[0] + x;
    }
    /// Position of cell (x, y, z)'s centre along `axis`.
    double cellCentre(int axis, int position) const {
        return origin[axis] + (position + 0.5) * spacing[axis];
    }

    /// Positions of normal-`axis` faces along each axis.
    std::array<int, 3> faceExtent(int axis) const {
        std::array<int, 3> e = cells;
        if (!periodic[axis]) e[axis] += 1;
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
    /// The normal-`axis` face on the upper side of cell (x, y, z) (across the seam on a periodic
    /// axis).
    std::int64_t upperFaceIndex(int axis, int x, int y, int z) const {
        std::array<int, 3> p{x, y, z};
        p[axis] = p[axis] + 1 == cells[axis] && periodic[axis] ? 0 : p[axis] + 1;
        return faceIndex(axis, p[0], p[1], p[2]);
    }
    /// Whether the normal-`axis` faces at `position` are a wall of the box: positions 0 and n
    /// along a non-periodic axis the air does not flow through, on a side that is not open.
    bool isWallFace(int axis, int position) const {
        if (periodic[axis] || flowThrough[axis]) return false;
        if (position == 0) return !open[std::size_t(2 * axis)];
        return position == cells[axis] && !open[std::size_t(2 * axis + 1)];
    }
    /// Bit a set when axis a is periodic: the `periodic` word of the device kernels' parameters.
    std::uint32_t periodicBits() const {
        return std::uint32_t(periodic[0]) | std::uint32_t(periodic[1]) << 1 |
               std::uint32_t(periodic[2]) << 2;
    }
    /// Whether the air may cross a side across `axis`: a wind blows along it, or one is open.
    bool crossesSide(int axis) const {
        return flowThrough[axis] || open[std::size_t(2 * axis)] || open[std::size_t(2 * axis + 1)];
    }
    /// Bit 2·axis + (0 low, 1 high) set when the air may cross that side (open, or a wind's): what
    /// is carried across it leaves the box (particles, engine/simulation/ParticleMotion.h).
    std::uint32_t crossableSideBits() const {
        std::uint32_t bits = 0;
        for (int side = 0; side < 2 * dim; ++side)
            if (open[std::size_t(side)] || flowThrough[std::size_t(side / 2)]) bits |= 1u << side;
        return bits;
    }
    /// periodicBits(), and bit 3 + a set when the air may cross a side across axis a
    /// (crossesSide): the `boundary` word of the kernels that sample the air's velocity
    /// (shaders/AxisStencil.glsl's isPeriodic and flowsThrough). The kernels then read the faces
    /// of both sides as the field holds them: 0 on a side that stays a wall, as no DOF writes it.
    std::uint32_t boundaryBits() const {
        return periodicBits() |
               (std::uint32_t(crossesSide(0)) | std::uint32_t(crossesSide(1)) << 1 |
                std::uint32_t(crossesSide(2)) << 2)
                   << 3;
    }
    /// Length of the box along `axis`.
    double length(int axis) const { return cells[axis] * spacing[axis]; }
    /// The smallest cell size over the grid's `dim` axes.
    double smallestSpacing() const {
        double h = spacing[0];
        for (int a = 1; a < dim; ++a) h = spacing[a] < h ? spacing[a] : h;
        return h;
    }
    /// `position` along `axis` brought into 0 … cells − 1 on a periodic axis; as is on others.
    int wrap(int axis, int position) const {
        if (!periodic[axis]) return position;
        const int n = cells[axis];
        return ((position % n) + n) % n;
    }
    /// The shortest of the offsets a whole number of box lengths apart along each periodic axis
    /// (the minimum image); the other components exactly as given.
    Vec3 minimumImage(Vec3 offset) const;
    /// `point` moved by whole box lengths along periodic axes to lie nearest `to`; the other
    /// coordinates exactly as given.
    Vec3 nearestImage(Vec3 point, const Vec3& to) const;

    /// Area of a whole normal-`axis` face (a length in 2D).
    double faceArea(int axis) const;
    double cellVolume() const { return spacing[0] * spacing[1] * spacing[2]; }
};

}  // namespace modeflow
