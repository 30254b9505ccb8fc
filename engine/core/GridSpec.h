#pragma once
/// @file GridSpec.h
/// The regular grid every stage works on: its cells between two corners. A plain value shared by
/// the precompute, the cache and the runtime.

#include <array>
#include <cstddef>

namespace modeflow {

using Vec3 = std::array<double, 3>;  ///< 2D scenes leave the third entry at 0.

/// Regular grid of cells between two corners. 2D grids have dim == 2 and resolution[2] == 1.
/// Along a periodic axis the box is no wall: its two ends are the same plane (a torus, a
/// channel), and every field wraps around. An open side (`[grid] open`) is no wall either: the
/// air may cross it, its pressure held at 0 and its tangential velocity at 0 there.
struct GridSpec {
    int dim = 2;
    std::array<int, 3> resolution{1, 1, 1};
    Vec3 boundsMin{0.0, 0.0, 0.0};
    Vec3 boundsMax{1.0, 1.0, 1.0};
    std::array<bool, 3> periodic{false, false, false};
    /// Per side, 2·axis + (0 the low side, 1 the high side): the air may cross it.
    std::array<bool, 6> open{false, false, false, false, false, false};

    double spacing(int axis) const {
        return (boundsMax[axis] - boundsMin[axis]) / resolution[axis];
    }
    bool isPeriodic(int axis) const { return periodic[axis]; }
    bool anyPeriodic() const { return periodic[0] || periodic[1] || periodic[2]; }
    /// Whether the low (`high` false) or high side across `axis` is open.
    bool isOpen(int axis, bool high) const { return open[std::size_t(2 * axis + (high ? 1 : 0))]; }
    /// Whether either side across `axis` is open.
    bool opensAxis(int axis) const { return isOpen(axis, false) || isOpen(axis, true); }
    bool anyOpen() const { return opensAxis(0) || opensAxis(1) || opensAxis(2); }
    bool operator==(const GridSpec&) const = default;
};

}  // namespace modeflow
