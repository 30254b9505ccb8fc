/// @file SurfaceImage.cpp

#include "engine/preview/SurfaceImage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/Palette.h"

namespace modeflow::preview {
namespace {

using V3 = std::array<double, 3>;

V3 sub(const V3& a, const V3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 unit(const V3& a) {
    const double n = std::sqrt(dot(a, a));
    return {a[0] / n, a[1] / n, a[2] / n};
}

/// The surface's own colour where it carries no dye.
constexpr Rgba kSurface{196, 202, 214, 255};

}  // namespace

Image surfaceImage(const TriangleMesh& mesh, std::span<const double> dye, double dyeScale,
                   int width, int height, const SurfaceCamera& camera) {
    if (dye.size() != mesh.vertices.size())
        throw Error("surface picture: " + std::to_string(dye.size()) + " dye values for " +
                    std::to_string(mesh.vertices.size()) + " vertices");
    if (width < 8 || height < 8) throw Error("surface picture: at least 8 × 8 pixels");
    const SurfaceProjection projection(mesh, camera, width, height);
    std::vector<std::array<double, 3>> screen(mesh.vertices.size());  // x, y (pixels), depth
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        screen[v] = projection.toPicture(mesh.vertices[v]);
    const V3 light = projection.light();
    Image image(width, height, palette::kBackground);
    std::vector<double> depth(std::size_t(width) * std::size_t(height),
                              -std::numeric_limits<double>::infinity());
    for (const auto& tri : mesh.triangles) {
        const auto& a = screen[std::size_t(tri[0])];
        const auto& b = screen[std::size_t(tri[1])];
        const auto& c = screen[std::size_t(tri[2])];
        const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (area >= 0.0) continue;  // facing away (y runs down: front faces have negative area)
        const V3 n = unit(
            cross(sub(mesh.vertices[std::size_t(tri[1])], mesh.vertices[std::size_t(tri[0])]),
                  sub(mesh.vertices[std::size_t(tri[2])], mesh.vertices[std::size_t(tri[0])])));
        const double shade = 0.35 + 0.65 * std::max(0.0, dot(n, light));
        const int x0 = std::max(0, int(std::floor(std::min({a[0], b[0], c[0]}))));
        const int x1 = std::min(width - 1, int(std::ceil(std::max({a[0], b[0], c[0]}))));
        const int y0 = std::max(0, int(std::floor(std::min({a[1], b[1], c[1]}))));
        const int y1 = std::min(height - 1, int(std::ceil(std::max({a[1], b[1], c[1]}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                const double wa = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
                const double wb = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
                const double z = wa * a[2] + wb * b[2] + wc * c[2];
                double& nearest = depth[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                if (z <= nearest) continue;
                nearest = z;
                const double value = wa * dye[std::size_t(tri[0])] + wb * dye[std::size_t(tri[1])] +
                                     wc * dye[std::size_t(tri[2])];
                const double t = std::clamp(value / dyeScale, 0.0, 1.0);
                Rgba colour{0, 0, 0, 255};
                for (int k = 0; k < 3; ++k)
                    colour[std::size_t(k)] =
                        std::uint8_t(std::lround(shade * ((1.0 - t) * kSurface[std::size_t(k)] +
                                                          t * palette::kHotSmoke[std::size_t(k)])));
                image.setPixel(x, y, colour);
            }
    }
    return image;
}

}  // namespace modeflow::preview
