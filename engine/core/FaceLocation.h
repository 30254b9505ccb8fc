#pragma once
/// @file FaceLocation.h
/// A face number of MacGrid's numbering taken apart (normal axis and lower-corner position), and
/// the per-DOF facts the reconstruction and force projection need. The inverse of
/// MacGrid::faceIndex; the device kernels decode face numbers the same way.

#include <array>
#include <cstdint>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"

namespace modeflow {

struct FaceLocation {
    int axis = 0;  ///< normal axis
    std::array<int, 3> pos{0, 0,
                           0};  ///< lower corner: the face lies between cells pos − e_axis and pos
};

/// @throw modeflow::Error when `face` is not a face of `grid`.
inline FaceLocation locateFace(const MacGrid& grid, std::int64_t face) {
    if (face < 0 || face >= grid.faceTotal())
        throw Error("face " + std::to_string(face) + " is outside the grid's " +
                    std::to_string(grid.faceTotal()) + " faces");
    FaceLocation location;
    while (location.axis + 1 < grid.dim && face >= grid.faceOffset(location.axis + 1))
        ++location.axis;
    const std::array<int, 3> e = grid.faceExtent(location.axis);
    std::int64_t local = face - grid.faceOffset(location.axis);
    location.pos[0] = int(local % e[0]);
    local /= e[0];
    location.pos[1] = int(local % e[1]);
    location.pos[2] = int(local / e[1]);
    return location;
}

/// World position of the face's centre (unused 2D axis: 0).
inline Vec3 faceCentre(const MacGrid& grid, const FaceLocation& face) {
    Vec3 centre{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a)
        centre[a] = grid.origin[a] + (face.pos[a] + (a == face.axis ? 0.0 : 0.5)) * grid.spacing[a];
    return centre;
}

/// Calls visit(face, position) for every face normal to `normal`, in MacGrid::faceIndex order,
/// `position` its lower corner.
template <typename Visit>
void forEachFace(const MacGrid& grid, int normal, Visit&& visit) {
    const std::array<int, 3> extent = grid.faceExtent(normal);
    for (int z = 0; z < extent[2]; ++z)
        for (int y = 0; y < extent[1]; ++y)
            for (int x = 0; x < extent[0]; ++x)
                visit(grid.faceIndex(normal, x, y, z), std::array<int, 3>{x, y, z});
}

/// The "up" axis of buoyancy (scenes/README.md, "Scene files"): +y in 2D, +z in 3D.
inline int upAxis(const MacGrid& grid) {
    return grid.dim - 1;
}

}  // namespace modeflow
