#include "engine/preview/VolumeView.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/Error.h"

namespace modeflow::preview {
namespace {

using V3 = std::array<double, 3>;

constexpr double kFieldOfViewDeg = 40.0;  // across the shorter side of the picture

V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 normalized(const V3& v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / n, v[1] / n, v[2] / n};
}

}  // namespace

shaders::RenderVolumeParams volumeViewParams(const MacGrid& grid, int width, int height,
                                             float densityScale, const VolumeCamera& camera,
                                             std::uint32_t densityStride) {
    if (grid.dim != 3)
        throw Error("3D preview: the smoke grid is " + std::to_string(grid.dim) + "D, expected 3D");
    if (width < 1 || height < 1)
        throw Error("3D preview: picture size " + std::to_string(width) + " × " +
                    std::to_string(height) + " is not positive");
    if (!(densityScale >= 0.0f) || !std::isfinite(densityScale))
        throw Error("3D preview: density scale " + std::to_string(densityScale) +
                    " is not a finite non-negative number");
    if (!(camera.zoom > 0.0) || !std::isfinite(camera.zoom))
        throw Error("3D view: zoom " + std::to_string(camera.zoom) + " is not positive");
    if (!(camera.stepCells > 0.0) || !std::isfinite(camera.stepCells))
        throw Error("3D view: march step " + std::to_string(camera.stepCells) + " is not positive");

    // World lengths are measured in L, the box's largest side (t units, RenderVolumeParams.h).
    V3 side{}, centre{};
    for (int a = 0; a < 3; ++a) side[a] = grid.spacing[a] * grid.cells[a];
    const double L = std::max({side[0], side[1], side[2]});
    for (int a = 0; a < 3; ++a) centre[a] = grid.origin[a] + 0.5 * side[a];
    const double radius =
        0.5 * std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);

    const double deg = std::numbers::pi / 180.0;
    const V3 toEye{std::cos(camera.elevationDeg * deg) * std::cos(camera.azimuthDeg * deg),
                   std::cos(camera.elevationDeg * deg) * std::sin(camera.azimuthDeg * deg),
                   std::sin(camera.elevationDeg * deg)};
    const V3 forward{-toEye[0], -toEye[1], -toEye[2]};
    const V3 right = normalized(cross(forward, {0.0, 0.0, 1.0}));
    const V3 up = cross(right, forward);
    const double halfAngle = 0.5 * kFieldOfViewDeg * deg;
    const double distance = radius / std::sin(halfAngle) / camera.zoom;
    const double tanHalf = std::tan(halfAngle);
    const double shorter = std::min(width, height);
    const double tanX = tanHalf * width / shorter, tanY = tanHalf * height / shorter;

    shaders::RenderVolumeParams p{};
    p.width = std::uint32_t(width);
    p.height = std::uint32_t(height);
    p.cellsX = std::uint32_t(grid.cells[0]);
    p.cellsY = std::uint32_t(grid.cells[1]);
    p.cellsZ = std::uint32_t(grid.cells[2]);
    p.densityScale = densityScale;
    p.densityStride = densityStride;
    for (int a = 0; a < 3; ++a)
        if (grid.periodic[a]) p.periodic |= 1u << a;
    std::array<float*, 3> eye{&p.eyeX, &p.eyeY, &p.eyeZ}, base{&p.baseX, &p.baseY, &p.baseZ},
        dx{&p.dxX, &p.dxY, &p.dxZ}, dy{&p.dyX, &p.dyY, &p.dyZ},
        cellsPerT{&p.cellsPerTX, &p.cellsPerTY, &p.cellsPerTZ};
    double smallest = grid.spacing[0];
    for (int a = 0; a < 3; ++a) {
        const double eyeWorld = centre[a] + distance * toEye[a];
        *eye[a] = float((eyeWorld - grid.origin[a]) / grid.spacing[a]);
        // Pixel (x, y)'s direction is base + (x + ½) dx + (y + ½) dy: y grows downwards.
        *base[a] = float(forward[a] - tanX * right[a] + tanY * up[a]);
        *dx[a] = float(2.0 * tanX * right[a] / width);
        *dy[a] = float(-2.0 * tanY * up[a] / height);
        *cellsPerT[a] = float(L / grid.spacing[a]);
        smallest = std::min(smallest, grid.spacing[a]);
    }
    p.stepT = float(camera.stepCells * smallest / L);
    p.glassT = float(0.5 * smallest / L);
    p.pixelAngle = float(2.0 * tanHalf / shorter);
    p.hz = float(grid.spacing[2] / L);
    return p;
}

float checkedFlameScale(float flameScale) {
    if (!(flameScale >= 0.0f) || !std::isfinite(flameScale))
        throw Error("3D preview: flame scale " + std::to_string(flameScale) +
                    " is negative or not finite");
    return flameScale;
}

}  // namespace modeflow::preview
