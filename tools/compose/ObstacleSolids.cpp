#include "tools/compose/ObstacleSolids.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "engine/core/Error.h"
#include "precompute/geometry/MeshLevelSet.h"
#include "precompute/geometry/ObjMesh.h"

namespace modeflow {
namespace {

/// 2²⁵ floats, 128 MiB: a lattice beyond this is a mesh far larger than the grid.
constexpr double kMaxLatticeSamples = 33554432.0;

/// The finest spacing of the grid's axes.
double finestSpacing(const GridSpec& grid) {
    double h = std::numeric_limits<double>::infinity();
    for (int a = 0; a < grid.dim; ++a) h = std::min(h, grid.spacing(a));
    return h;
}

SolidLevelSet sampleMesh(const ObstacleSpec& spec, double spacing, const std::string& where) {
    const TriangleMesh mesh = readObjMesh(spec.meshFile);
    Vec3 lo = mesh.vertices.front(), hi = lo;
    for (const Vec3& p : mesh.vertices)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a]);
            hi[a] = std::max(hi[a], p[a]);
        }
    SolidLevelSet solid;
    solid.spacing = spacing;
    double total = 1.0;
    for (int a = 0; a < 3; ++a) {
        solid.origin[a] = lo[a] - 2.0 * spacing;
        const double samples = std::ceil((hi[a] - lo[a]) / spacing) + 5.0;
        total *= samples;
        if (total > kMaxLatticeSamples)
            throw Error(where + ": the mesh spans " + std::to_string(hi[a] - lo[a]) + " along " +
                        "xyz"[a] + " at scale " + std::to_string(spec.scale) +
                        "; its level set, sampled every half grid cell, would need more than " +
                        std::to_string(std::int64_t(kMaxLatticeSamples)) +
                        " samples: the mesh is far larger than the grid (are its units or "
                        "scale right?)");
        solid.samples[a] = int(samples);
    }
    const auto shape = loadMeshShape(spec.meshFile, spacing);
    solid.depth.resize(std::size_t(total));
    std::size_t i = 0;
    for (int z = 0; z < solid.samples[2]; ++z)
        for (int y = 0; y < solid.samples[1]; ++y)
            for (int x = 0; x < solid.samples[0]; ++x)
                solid.depth[i++] = float(
                    shape->value({solid.origin[0] + x * spacing, solid.origin[1] + y * spacing,
                                  solid.origin[2] + z * spacing}));
    return solid;
}

/// In a 2D scene the obstacle is the mesh's section by the plane z = 0 (turning about z keeps
/// it there): refuse a mesh that section misses.
void requireCrossesThePlane(const SolidLevelSet& solid, const std::string& where) {
    const int steps = 4 * std::max(solid.samples[0], solid.samples[1]);
    for (int j = 0; j <= steps; ++j)
        for (int i = 0; i <= steps; ++i) {
            const Vec3 p{solid.origin[0] + (solid.samples[0] - 1) * solid.spacing * i / steps,
                         solid.origin[1] + (solid.samples[1] - 1) * solid.spacing * j / steps, 0.0};
            if (solid.depthAt(p) >= 0.0) return;
        }
    throw Error(where +
                ": in a 2D scene an obstacle is its mesh's section by the plane z = 0, and this "
                "mesh does not cross that plane (move the mesh's vertices so that it does)");
}

}  // namespace

std::vector<std::shared_ptr<const SolidLevelSet>> obstacleSolids(const SceneSpec& scene) {
    std::vector<std::shared_ptr<const SolidLevelSet>> solids;
    std::map<std::pair<std::filesystem::path, double>, std::shared_ptr<const SolidLevelSet>> made;
    const double h = finestSpacing(scene.grid);
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        const ObstacleSpec& spec = scene.obstacles[o];
        if (spec.shape != ObstacleShape::Mesh) {
            solids.emplace_back();
            continue;
        }
        std::shared_ptr<const SolidLevelSet>& solid = made[{spec.meshFile, spec.scale}];
        if (!solid) {
            const std::string where = scene.sourceFile.string() + ": [[obstacle]] #" +
                                      std::to_string(o + 1) + " (" + spec.meshFile.string() + ")";
            try {
                solid = std::make_shared<const SolidLevelSet>(
                    sampleMesh(spec, 0.5 * h / spec.scale, where));
            } catch (const Error& e) {
                if (std::string(e.what()).rfind(where, 0) == 0) throw;
                throw Error(scene.sourceFile.string() + ": [[obstacle]] #" + std::to_string(o + 1) +
                            ": " + e.what());
            }
            if (scene.grid.dim == 2) requireCrossesThePlane(*solid, where);
        }
        solids.push_back(solid);
    }
    return solids;
}

void attachObstacleSolids(std::vector<MovingObstacle>& obstacles,
                          const std::vector<std::shared_ptr<const SolidLevelSet>>& solids) {
    if (solids.size() != obstacles.size())
        throw Error("attachObstacleSolids: " + std::to_string(solids.size()) + " level sets for " +
                    std::to_string(obstacles.size()) + " obstacles");
    for (std::size_t o = 0; o < obstacles.size(); ++o) obstacles[o].levelSet = solids[o];
}

}  // namespace modeflow
