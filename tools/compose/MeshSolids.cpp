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
#include "precompute/geometry/ObjMesh.h"
#include "tools/compose/DeformingSolids.h"
#include "tools/compose/MeshLattice.h"

namespace modeflow {
namespace {

/// `file`'s depth sampled every `spacing` mesh units, exact to `depth` inside (deeper the level
/// set's band holds a constant); `scale`: world length per mesh unit (for messages).
SolidLevelSet sampleMesh(const std::filesystem::path& file, double scale, double spacing,
                         double depth, const std::string& where) {
    const TriangleMesh mesh = readObjMesh(file);
    const auto [lo, hi] = meshBounds(mesh);
    SolidLevelSet solid = latticeOver(lo, hi, spacing, scale, where);
    sampleDepth(solid, mesh, file, depth);
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

ObstacleShapes obstacleSolids(const SceneSpec& scene) {
    const double spacing = 0.5 * finestSpacing(scene.grid);
    const auto rigid =
        meshSolids(scene, "[[obstacle]]", scene.obstacles.size(), spacing, [&](std::size_t i) {
            const ObstacleSpec& o = scene.obstacles[i];
            return o.shape == ObstacleShape::Mesh && o.sequenceRate == 0.0
                       ? std::optional(MeshUse{o.meshFile, o.scale, 0.0})
                       : std::nullopt;
        });
    ObstacleShapes shapes(scene.obstacles.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (rigid[i]) {
            shapes[i] = {rigid[i]};
        } else if (scene.obstacles[i].sequenceRate > 0.0) {
            shapes[i] = deformingSolids(scene, i, spacing);
            if (scene.grid.dim == 2)
                requireCrossesThePlane(
                    *shapes[i].front(),
                    scene.sourceFile.string() + ": [[obstacle]] #" + std::to_string(i + 1));
        }
    }
    return shapes;
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

void attachObstacleSolids(std::vector<MovingObstacle>& obstacles, const ObstacleShapes& solids) {
    std::vector<std::shared_ptr<const SolidLevelSet>> first;
    for (const auto& shapes : solids) first.push_back(shapes.empty() ? nullptr : shapes.front());
    attachSolids(obstacles, first, "obstacles");
    for (std::size_t i = 0; i < obstacles.size(); ++i)
        obstacles[i].sequence = solids[i].size() > 1 || obstacles[i].spec.sequenceRate > 0.0
                                    ? solids[i]
                                    : std::vector<std::shared_ptr<const SolidLevelSet>>{};
}

void attachSourceSolids(std::vector<SmokeEmitter>& emitters,
                        const std::vector<std::shared_ptr<const SolidLevelSet>>& solids) {
    attachSolids(emitters, solids, "sources");
}

}  // namespace modeflow
