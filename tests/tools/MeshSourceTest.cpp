/// @file MeshSourceTest.cpp
/// Mesh sources (`[[source]] shape = "mesh"`): an icosphere's volume emits into the cells the
/// analytic ball would, a shell of `thickness` only near its surface, and a mesh that is no closed
/// surface is refused naming the source.

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/MacGrid.h"
#include "engine/simulation/SmokeEmitter.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/TestFolder.h"
#include "tests/support/ThrownMessage.h"
#include "tools/compose/MeshSolids.h"

namespace modeflow {
namespace {

/// A 32³ grid over the unit cube with a mesh source of `mesh` (written into `folder`).
SceneSpec meshSourceScene(const testing::TestFolder& folder, const TriangleMesh& mesh,
                          double thickness = 0.0) {
    SceneSpec scene;
    scene.sourceFile = folder / "s.toml";
    scene.grid.dim = 3;
    scene.grid.resolution = {32, 32, 32};
    scene.grid.boundsMin = {0.0, 0.0, 0.0};
    scene.grid.boundsMax = {1.0, 1.0, 1.0};
    SourceSpec source;
    source.shape.kind = ShapeKind::Mesh;
    source.shape.meshFile = folder / "source.obj";
    source.thickness = thickness;
    writeObj(source.shape.meshFile, mesh);
    scene.sources = {source};
    return scene;
}

/// The density rate per cell of `emitter` on the scene's grid (every cell fluid).
std::vector<double> emitted(const SceneSpec& scene, const SmokeEmitter& emitter) {
    const MacGrid grid = MacGrid::fromSpec(scene.grid);
    const auto cells = std::size_t(grid.cellCount());
    std::vector<double> density(cells, 0.0), temperature(cells, 0.0);
    const std::vector<std::uint8_t> fluid(cells, 1);
    applyEmitters(grid, fluid, std::span(&emitter, 1), 1.0, density, temperature);
    return density;
}

SmokeEmitter meshEmitter(const SceneSpec& scene) {
    std::vector<SmokeEmitter> emitters{emitterFromSource(scene.sources[0])};
    attachSourceSolids(emitters, sourceSolids(scene));
    return emitters[0];
}

TEST(MeshSource, AnIcosphereEmitsWhereTheBallWould) {
    const testing::TestFolder folder;
    const Vec3 centre{0.5, 0.45, 0.55};
    const SceneSpec scene = meshSourceScene(folder, makeIcosphere(3, 0.25, centre));
    SmokeEmitter ball;
    ball.centre = centre;
    ball.radius = 0.25;
    ball.densityRate = 1.0;
    SmokeEmitter mesh = meshEmitter(scene);
    mesh.densityRate = 1.0;
    const std::vector<double> fromMesh = emitted(scene, mesh), fromBall = emitted(scene, ball);
    int covered = 0, differ = 0;
    for (std::size_t c = 0; c < fromBall.size(); ++c) {
        covered += fromBall[c] > 0.0;
        differ += (fromBall[c] > 0.0) != (fromMesh[c] > 0.0);
    }
    std::cout << "the ball emits into " << covered << " cells, the icosphere differs on " << differ
              << "\n";
    EXPECT_GT(covered, 2000);
    EXPECT_LE(differ, covered / 50);
}

TEST(MeshSource, AShellEmitsOnlyNearItsSurface) {
    const testing::TestFolder folder;
    const Vec3 centre{0.5, 0.5, 0.5};
    const SceneSpec scene = meshSourceScene(folder, makeIcosphere(3, 0.3, centre), 0.06);
    SmokeEmitter shell = meshEmitter(scene);
    shell.densityRate = 1.0;
    const std::vector<double> rates = emitted(scene, shell);
    const MacGrid grid = MacGrid::fromSpec(scene.grid);
    int emitting = 0;
    double nearest = 1.0, farthest = 0.0;
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                if (rates[std::size_t(grid.cellIndex(x, y, z))] == 0.0) continue;
                ++emitting;
                const double r =
                    std::hypot(grid.cellCentre(0, x) - 0.5, grid.cellCentre(1, y) - 0.5,
                               grid.cellCentre(2, z) - 0.5);
                nearest = std::min(nearest, r);
                farthest = std::max(farthest, r);
            }
    std::cout << emitting << " cells emit, from r = " << nearest << " to " << farthest << "\n";
    EXPECT_GT(emitting, 500);
    EXPECT_GE(nearest, 0.3 - 0.06 - 0.01) << "nothing deeper than the shell";
    EXPECT_LE(farthest, 0.3 + 0.01) << "nothing outside the mesh";
}

TEST(MeshSource, AnOpenMeshIsRefusedNamingTheSource) {
    const testing::TestFolder folder;
    SceneSpec scene = meshSourceScene(folder, makeIcosphere(1, 0.2, {0.5, 0.5, 0.5}));
    std::ofstream(scene.sources[0].shape.meshFile) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string what = testing::thrownMessage([&] { sourceSolids(scene); });
    EXPECT_NE(what.find("[[source]] #1"), std::string::npos) << what;
    EXPECT_NE(what.find("belongs to no other triangle"), std::string::npos) << what;
}

}  // namespace
}  // namespace modeflow
