#include "tools/compose/MeshSolids.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
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

/// `file`'s depth sampled every `spacing` mesh units, exact to `depth` inside (deeper the level
/// set's band holds a constant); `scale`: world length per mesh unit (for messages).
SolidLevelSet sampleMesh(const std::filesystem::path& file, double scale, double spacing,
                         double depth, const std::string& where) {
    const TriangleMesh mesh = readObjMesh(file);
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
                        "xyz"[a] + " at scale " + std::to_string(scale) +
                        "; its level set, sampled every half grid cell, would need more than " +
                        std::to_string(std::int64_t(kMaxLatticeSamples)) +
                        " samples: the mesh is far larger than the grid (are its units or "
                        "scale right?)");
        solid.samples[a] = int(samples);
    }
    const auto shape =
        loadMeshShape(mesh, file, spacing, std::max(3.0, std::ceil(depth / spacing) + 2.0));
    solid.depth.resize(std::size_t(total));
    std::size_t i = 0;
    for (int z = 0; z < solid.samples[2]; ++z)
        for (int y = 0; y < solid.samples[1]; ++y)
            for (int x = 0; x < solid.samples[0]; ++x)
                solid.depth[i++] = float(
                    shape->value({solid.origin[0] + x * spacing, solid.origin[1] + y * spacing,
                                  solid.origin[2] + z * spacing}));
    // The solid lies inside its vertices' hull; trilinear depth may reach a diagonal beyond.
    for (const Vec3& p : mesh.vertices)
        solid.radius = std::max(solid.radius, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    solid.radius += std::sqrt(3.0) * spacing;
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

/// The level sets of `count` entries of `section` ([[obstacle]] or [[source]]): `meshOf(i)` gives
/// entry i's file, scale and the depth to which it must be exact (a shell's thickness), or
/// nothing when it is no mesh. Equal ones share a level set.
/// A mesh file at a scale, sampled exactly to a depth inside.
struct MeshUse {
    std::filesystem::path file;
    double scale = 1.0;
    double depth = 0.0;
    bool operator<(const MeshUse& other) const {
        return std::tie(file, scale, depth) < std::tie(other.file, other.scale, other.depth);
    }
};

template <typename MeshOf>
std::vector<std::shared_ptr<const SolidLevelSet>> meshSolids(const SceneSpec& scene,
                                                             const char* section, std::size_t count,
                                                             double spacing, MeshOf meshOf) {
    std::vector<std::shared_ptr<const SolidLevelSet>> solids;
    std::map<MeshUse, std::shared_ptr<const SolidLevelSet>> made;
    for (std::size_t i = 0; i < count; ++i) {
        const std::optional<MeshUse> mesh = meshOf(i);
        if (!mesh) {
            solids.emplace_back();
            continue;
        }
        const auto& [file, scale, depth] = *mesh;
        std::shared_ptr<const SolidLevelSet>& solid = made[*mesh];
        if (!solid) {
            const std::string entry =
                scene.sourceFile.string() + ": " + section + " #" + std::to_string(i + 1);
            const std::string where = entry + " (" + file.string() + ")";
            try {
                solid = std::make_shared<const SolidLevelSet>(
                    sampleMesh(file, scale, spacing / scale, depth / scale, where));
            } catch (const Error& e) {
                if (std::string(e.what()).rfind(where, 0) == 0) throw;
                throw Error(entry + ": " + e.what());
            }
            if (scene.grid.dim == 2) requireCrossesThePlane(*solid, where);
        }
        solids.push_back(solid);
    }
    return solids;
}

/// Hands item i `solids[i]` (obstacles or emitters, each with a `levelSet`).
template <typename Items>
void attachSolids(Items& items, const std::vector<std::shared_ptr<const SolidLevelSet>>& solids,
                  const char* what) {
    if (solids.size() != items.size())
        throw Error("attaching mesh level sets: " + std::to_string(solids.size()) + " for " +
                    std::to_string(items.size()) + " " + what);
    for (std::size_t i = 0; i < items.size(); ++i) items[i].levelSet = solids[i];
}

}  // namespace

std::vector<std::shared_ptr<const SolidLevelSet>> obstacleSolids(const SceneSpec& scene) {
    return meshSolids(scene, "[[obstacle]]", scene.obstacles.size(),
                      0.5 * finestSpacing(scene.grid), [&](std::size_t i) {
                          const ObstacleSpec& o = scene.obstacles[i];
                          return o.shape == ObstacleShape::Mesh
                                     ? std::optional(MeshUse{o.meshFile, o.scale, 0.0})
                                     : std::nullopt;
                      });
}

std::vector<std::shared_ptr<const SolidLevelSet>> sourceSolids(const SceneSpec& scene) {
    return meshSolids(
        scene, "[[source]]", scene.sources.size(),
        0.5 * finestSpacing(scene.grid) / scene.smoke.resolutionScale, [&](std::size_t i) {
            const SourceSpec& source = scene.sources[i];
            return source.shape.kind == ShapeKind::Mesh
                       ? std::optional(MeshUse{source.shape.meshFile, 1.0, source.thickness})
                       : std::nullopt;
        });
}

void attachObstacleSolids(std::vector<MovingObstacle>& obstacles,
                          const std::vector<std::shared_ptr<const SolidLevelSet>>& solids) {
    attachSolids(obstacles, solids, "obstacles");
}

void attachSourceSolids(std::vector<SmokeEmitter>& emitters,
                        const std::vector<std::shared_ptr<const SolidLevelSet>>& solids) {
    attachSolids(emitters, solids, "sources");
}

}  // namespace modeflow
