#include "engine/preview/ParticleDots.h"

#include <cmath>

#include "engine/preview/Palette.h"

namespace modeflow::preview {
namespace {

using V3 = std::array<double, 3>;

double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// A dot centred at pixel coordinates (x, y) (pixel centres at half-integers): the centre pixel
/// and its four neighbours, the neighbours half blended.
void drawDot(Image& picture, double x, double y) {
    if (!(x >= 0.0 && y >= 0.0 && x < picture.width && y < picture.height)) return;
    const int cx = int(x), cy = int(y);
    constexpr int offsets[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int k = 0; k < 5; ++k) {
        const int px = cx + offsets[k][0], py = cy + offsets[k][1];
        if (px < 0 || py < 0 || px >= picture.width || py >= picture.height) continue;
        const double alpha = k == 0 ? 1.0 : 0.5;
        const std::size_t o = picture.offset(px, py);
        for (int c = 0; c < 3; ++c)
            picture.rgba[o + std::size_t(c)] = std::uint8_t(std::lround(
                (1.0 - alpha) * picture.rgba[o + std::size_t(c)] + alpha * palette::kParticle[c]));
    }
}

}  // namespace

void drawParticles2D(Image& picture, const MacGrid& smokeGrid, int pixelsPerCell,
                     std::span<const double> positions) {
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
        const double gx = (positions[i] - smokeGrid.origin[0]) / smokeGrid.spacing[0];
        const double gy = (positions[i + 1] - smokeGrid.origin[1]) / smokeGrid.spacing[1];
        drawDot(picture, gx * pixelsPerCell, picture.height - gy * pixelsPerCell);
    }
}

void drawParticles3D(Image& picture, const MacGrid& smokeGrid,
                     const shaders::RenderVolumeParams& view, std::span<const double> positions) {
    // The camera's frame from its pixel rays: pixel (x, y) looks along base + (x+½)dx + (y+½)dy.
    const V3 base{view.baseX, view.baseY, view.baseZ}, dx{view.dxX, view.dxY, view.dxZ},
        dy{view.dyX, view.dyY, view.dyZ};
    const V3 eyeCells{view.eyeX, view.eyeY, view.eyeZ};
    V3 forward, eye;
    for (int a = 0; a < 3; ++a) {
        forward[a] = base[a] + 0.5 * view.width * dx[a] + 0.5 * view.height * dy[a];
        eye[a] = smokeGrid.origin[a] + eyeCells[a] * smokeGrid.spacing[a];
    }
    const double dx2 = dot(dx, dx), dy2 = dot(dy, dy);
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
        V3 d{positions[i] - eye[0], positions[i + 1] - eye[1], positions[i + 2] - eye[2]};
        const double ahead = dot(d, forward) / dot(forward, forward);
        if (!(ahead > 0.0)) continue;
        for (int a = 0; a < 3; ++a) d[a] = d[a] / ahead - base[a];
        drawDot(picture, dot(d, dx) / dx2, dot(d, dy) / dy2);
    }
}

}  // namespace modeflow::preview
