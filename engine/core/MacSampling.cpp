#include "engine/core/MacSampling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

/// Linear interpolation along one axis between positions `lo` and `hi` = lo + 1, or a single
/// position (hi == lo, f = 0) on a one-point axis.
struct AxisStencil {
    int lo = 0;
    int hi = 0;
    double f = 0.0;  ///< weight of `hi`
};

/// Along an axis with `n` samples at grid coordinates offset + 0, 1, …, n − 1, clamped to them;
/// on a periodic axis the samples repeat every n, and the stencil wraps (n − 1 to 0).
AxisStencil axisStencil(double coordinate, double offset, int n, bool periodic) {
    AxisStencil a;
    if (periodic) {
        double s = std::fmod(coordinate - offset, double(n));  // exact, (−n, n)
        if (s < 0.0) s += n;                                   // [0, n], n only by round-off
        const double below = std::floor(s);
        a.lo = int(below) % n;
        a.hi = (a.lo + 1) % n;
        a.f = s - below;
        return a;
    }
    const double s = std::clamp(coordinate - offset, 0.0, double(n - 1));
    a.lo = std::min(int(std::floor(s)), std::max(n - 2, 0));
    a.hi = std::min(a.lo + 1, n - 1);
    a.f = s - a.lo;
    return a;
}

/// The distinct corners of a trilinear stencil, x fastest (the device's loop order), and weights.
struct Corners {
    std::array<std::array<int, 3>, 8> position{};
    std::array<double, 8> weight{};
    int count = 0;
};

/// The stencil at `gridPoint` on a lattice of extent[a] points along axis a, at grid coordinates
/// offset[a] + 0, 1, … (cell centres: offset ½; face positions along their normal: offset 0),
/// wrapping along the grid's periodic axes.
Corners trilinearCorners(const std::array<int, 3>& extent, const std::array<bool, 3>& periodic,
                         const Vec3& offset, const Vec3& gridPoint) {
    Corners corners;
    // A diverged state moves points to NaN or infinity: no stencil (floor of NaN is no index).
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(gridPoint[a])) return corners;
    std::array<AxisStencil, 3> s;
    for (int a = 0; a < 3; ++a) s[a] = axisStencil(gridPoint[a], offset[a], extent[a], periodic[a]);
    for (int cz = 0; cz <= (s[2].hi != s[2].lo); ++cz)
        for (int cy = 0; cy <= (s[1].hi != s[1].lo); ++cy)
            for (int cx = 0; cx <= (s[0].hi != s[0].lo); ++cx) {
                corners.position[corners.count] = {cx ? s[0].hi : s[0].lo, cy ? s[1].hi : s[1].lo,
                                                   cz ? s[2].hi : s[2].lo};
                corners.weight[corners.count] = (cx ? s[0].f : 1.0 - s[0].f) *
                                                (cy ? s[1].f : 1.0 - s[1].f) *
                                                (cz ? s[2].f : 1.0 - s[2].f);
                ++corners.count;
            }
    return corners;
}

}  // namespace

Vec3 worldToGrid(const MacGrid& grid, const Vec3& world) {
    Vec3 g;
    for (int a = 0; a < 3; ++a) g[a] = (world[a] - grid.origin[a]) / grid.spacing[a];
    return g;
}

CellStencil cellStencil(const MacGrid& grid, const Vec3& gridPoint) {
    const Corners corners = trilinearCorners(grid.cells, grid.periodic, {0.5, 0.5, 0.5}, gridPoint);
    CellStencil stencil;
    stencil.count = corners.count;
    for (int c = 0; c < corners.count; ++c) {
        const std::array<int, 3>& p = corners.position[c];
        stencil.cell[c] = grid.cellIndex(p[0], p[1], p[2]);
        stencil.weight[c] = corners.weight[c];
    }
    return stencil;
}

double sampleCells(const MacGrid& grid, std::span<const double> field, const Vec3& world) {
    if (field.size() != std::size_t(grid.cellCount()))
        throw Error("sampleCells: the cell field has " + std::to_string(field.size()) +
                    " values, the grid " + std::to_string(grid.cellCount()) + " cells");
    const CellStencil stencil = cellStencil(grid, worldToGrid(grid, world));
    double value = 0.0;
    for (int c = 0; c < stencil.count; ++c) value += stencil.weight[c] * field[stencil.cell[c]];
    return value;
}

template <typename T>
double sampleFaceComponent(const MacGrid& grid, std::span<const T> faces, int axis,
                           const Vec3& gridPoint) {
    if (axis >= grid.dim) return 0.0;
    // Face positions along the normal sit on integer coordinates, along the others at centres.
    Vec3 offset{0.5, 0.5, 0.5};
    offset[axis] = 0.0;
    const Corners corners =
        trilinearCorners(grid.faceExtent(axis), grid.periodic, offset, gridPoint);
    double value = 0.0;
    for (int c = 0; c < corners.count; ++c) {
        const std::array<int, 3>& p = corners.position[c];
        if (grid.isWallFace(axis, p[axis])) continue;
        value += corners.weight[c] * double(faces[grid.faceIndex(axis, p[0], p[1], p[2])]);
    }
    return value;
}

template <typename T>
Vec3 sampleVelocityGrid(const MacGrid& grid, std::span<const T> faces, const Vec3& gridPoint) {
    requireFaceField(grid, faces.size(), "sampleVelocity");
    return {sampleFaceComponent(grid, faces, 0, gridPoint),
            sampleFaceComponent(grid, faces, 1, gridPoint),
            sampleFaceComponent(grid, faces, 2, gridPoint)};
}

void requireFaceField(const MacGrid& grid, std::size_t size, const char* what) {
    if (size != std::size_t(grid.faceTotal()))
        throw Error(std::string(what) + ": the face field has " + std::to_string(size) +
                    " values, the " + std::to_string(grid.dim) + "D grid " +
                    std::to_string(grid.faceTotal()) + " faces");
}

template double sampleFaceComponent<float>(const MacGrid&, std::span<const float>, int,
                                           const Vec3&);
template double sampleFaceComponent<double>(const MacGrid&, std::span<const double>, int,
                                            const Vec3&);
template Vec3 sampleVelocityGrid<float>(const MacGrid&, std::span<const float>, const Vec3&);
template Vec3 sampleVelocityGrid<double>(const MacGrid&, std::span<const double>, const Vec3&);

}  // namespace modeflow
