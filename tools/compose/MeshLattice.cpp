#include "tools/compose/MeshLattice.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "engine/core/Error.h"
#include "precompute/geometry/MeshLevelSet.h"

namespace modeflow {

double finestSpacing(const GridSpec& grid) {
    double h = std::numeric_limits<double>::infinity();
    for (int a = 0; a < grid.dim; ++a) h = std::min(h, grid.spacing(a));
    return h;
}

std::pair<Vec3, Vec3> meshBounds(const TriangleMesh& mesh) {
    Vec3 lo = mesh.vertices.front(), hi = lo;
    for (const Vec3& p : mesh.vertices)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a]);
            hi[a] = std::max(hi[a], p[a]);
        }
    return {lo, hi};
}

SolidLevelSet latticeOver(const Vec3& lo, const Vec3& hi, double spacing, double scale,
                          const std::string& where) {
    SolidLevelSet solid;
    solid.spacing = spacing;
    double total = 1.0;
    for (int a = 0; a < 3; ++a) {
        solid.origin[a] = lo[a] - 2.0 * spacing;
        const double samples = std::ceil((hi[a] - lo[a]) / spacing) + 5.0;
        total *= samples;
        if (total > kMaxLatticeSamples)
            throw Error(where + ": the mesh spans " + std::to_string(hi[a] - lo[a]) + " along " +
                        "xyz"[a] + " at scale " + std::to_string(scale) +
                        "; its level set, sampled every half grid cell, would need more than " +
                        std::to_string(std::int64_t(kMaxLatticeSamples)) +
                        " samples: the mesh is far larger than the grid (are its units or "
                        "scale right?)");
        solid.samples[a] = int(samples);
    }
    return solid;
}

void sampleDepth(SolidLevelSet& solid, const TriangleMesh& mesh, const std::filesystem::path& file,
                 double depth) {
    const double spacing = solid.spacing;
    const auto shape =
        loadMeshShape(mesh, file, spacing, std::max(3.0, std::ceil(depth / spacing) + 2.0));
    solid.depth.resize(std::size_t(solid.samples[0]) * solid.samples[1] * solid.samples[2]);
    std::size_t i = 0;
    for (int z = 0; z < solid.samples[2]; ++z)
        for (int y = 0; y < solid.samples[1]; ++y)
            for (int x = 0; x < solid.samples[0]; ++x)
                solid.depth[i++] = float(
                    shape->value({solid.origin[0] + x * spacing, solid.origin[1] + y * spacing,
                                  solid.origin[2] + z * spacing}));
    // The solid lies inside its vertices' hull; trilinear depth may reach a diagonal beyond.
    solid.radius = 0.0;
    for (const Vec3& p : mesh.vertices)
        solid.radius = std::max(solid.radius, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    solid.radius += std::sqrt(3.0) * spacing;
}

}  // namespace modeflow
