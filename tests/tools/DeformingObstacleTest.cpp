/// @file DeformingObstacleTest.cpp
/// Deforming mesh obstacles (`file = "flag_####.obj"`, `sequence_rate`): the file shown at each
/// time, the material's velocity by vertex correspondence and, where the vertex counts differ,
/// from the level sets' motion, and a missing file named before any work.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/MacGrid.h"
#include "engine/core/MeshSequence.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/TestFolder.h"
#include "tests/support/ThrownMessage.h"
#include "tools/compose/MeshSolids.h"

namespace modeflow {
namespace {

/// A 16³ grid over the unit cube, 10 steps of 0.02 (the run ends at t = 0.2), with one mesh
/// obstacle at (0.5, 0.5, 0.5) showing the files `folder`/flag_####.obj at `rate`.
SceneSpec deformingScene(const testing::TestFolder& folder, double rate) {
    SceneSpec scene;
    scene.sourceFile = folder / "s.toml";
    scene.grid.dim = 3;
    scene.grid.resolution = {16, 16, 16};
    scene.grid.boundsMin = {0.0, 0.0, 0.0};
    scene.grid.boundsMax = {1.0, 1.0, 1.0};
    scene.simulation.dt = 0.02;
    scene.output.frames = 10;
    scene.output.stepsPerFrame = 1;
    ObstacleSpec obstacle;
    obstacle.shape = ObstacleShape::Mesh;
    obstacle.meshFile = folder / "flag_####.obj";
    obstacle.sequenceRate = rate;
    obstacle.path = {{0.0, {0.5, 0.5, 0.5}}};
    scene.obstacles = {obstacle};
    return scene;
}

MovingObstacle attached(const SceneSpec& scene) {
    std::vector<MovingObstacle> obstacles{MovingObstacle{scene.obstacles[0]}};
    attachObstacleSolids(obstacles, obstacleSolids(scene));
    return obstacles[0];
}

MacGrid gridOf(const SceneSpec& scene) {
    return MacGrid::fromSpec(scene.grid);
}

TEST(DeformingObstacle, ATranslatingSequenceCarriesItsMaterialAtItsVerticesSpeed) {
    // A ball of radius 0.2 moving 0.02 along x from file to file, ten files per unit time: the
    // run (to t = 0.2) shows files 1 to 3, each one where its file puts it, its material moving
    // at 0.2 along x.
    const testing::TestFolder folder;
    for (int k = 1; k <= 5; ++k)
        writeObj(sequenceFile(folder / "flag_####.obj", k),
                 makeIcosphere(2, 0.2, {0.02 * (k - 1), 0.0, 0.0}));
    const SceneSpec scene = deformingScene(folder, 10.0);
    const MovingObstacle obstacle = attached(scene);
    ASSERT_EQ(obstacle.sequence.size(), 3u);
    EXPECT_EQ(obstacle.levelSet, obstacle.sequence.front());
    EXPECT_EQ(obstacle.shapeAt(0.0), obstacle.sequence[0].get());
    EXPECT_EQ(obstacle.shapeAt(0.15), obstacle.sequence[1].get());
    EXPECT_EQ(obstacle.shapeAt(0.2), obstacle.sequence[2].get());
    EXPECT_EQ(obstacle.shapeAt(5.0), obstacle.sequence[2].get()) << "the last file holds";
    const MacGrid grid = gridOf(scene);
    // At t = 0.25 the third file's ball (centre x = 0.54) covers x = 0.72 but not 0.32, which
    // the first file's covers.
    const ObstaclePose pose = obstacle.poseAt(0.25);
    EXPECT_TRUE(obstacle.covers({0.72, 0.5, 0.5}, pose, grid));
    EXPECT_FALSE(obstacle.covers({0.32, 0.5, 0.5}, pose, grid));
    EXPECT_TRUE(obstacle.covers({0.32, 0.5, 0.5}, obstacle.poseAt(0.05), grid));
    for (const Vec3& point : {Vec3{0.54, 0.5, 0.5}, Vec3{0.62, 0.58, 0.45}, Vec3{0.45, 0.5, 0.5}}) {
        const Vec3 v = obstacle.velocityOf(point, pose, grid);
        EXPECT_NEAR(v[0], 0.2, 1e-6);
        EXPECT_NEAR(v[1], 0.0, 1e-6);
        EXPECT_NEAR(v[2], 0.0, 1e-6);
    }
    EXPECT_GE(obstacle.surfaceSpeedBound(0.0, 0.2), 0.2 - 1e-6);
}

TEST(DeformingObstacle, WithoutVertexCorrespondenceTheSurfaceMovesAsItsLevelSets) {
    // A ball growing from radius 0.2 to 0.22 between two files of different vertex counts, ten
    // files per unit time: its surface moves outward at 0.2.
    const testing::TestFolder folder;
    writeObj(sequenceFile(folder / "flag_####.obj", 1), makeIcosphere(3, 0.2));
    writeObj(sequenceFile(folder / "flag_####.obj", 2), makeIcosphere(4, 0.22));
    SceneSpec scene = deformingScene(folder, 10.0);
    scene.output.frames = 4;  // to t = 0.08: file 1 alone, its velocity towards file 2
    const MovingObstacle obstacle = attached(scene);
    ASSERT_EQ(obstacle.sequence.size(), 1u);
    const ObstaclePose pose = obstacle.poseAt(0.05);
    const MacGrid grid = gridOf(scene);
    for (const Vec3& direction : {Vec3{1.0, 0.0, 0.0}, Vec3{0.0, -0.6, 0.8}}) {
        const Vec3 point{0.5 + 0.195 * direction[0], 0.5 + 0.195 * direction[1],
                         0.5 + 0.195 * direction[2]};
        const Vec3 v = obstacle.velocityOf(point, pose, grid);
        const double outward = v[0] * direction[0] + v[1] * direction[1] + v[2] * direction[2];
        EXPECT_NEAR(outward, 0.2, 0.04) << direction[0] << " " << direction[1];
        const double along = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - outward * outward);
        EXPECT_LT(along, 0.04);
    }
}

TEST(DeformingObstacle, AMissingFileTheRunShowsIsNamedBeforeAnyWork) {
    const testing::TestFolder folder;
    for (const int k : {1, 2, 4})
        writeObj(sequenceFile(folder / "flag_####.obj", k), makeIcosphere(2, 0.2));
    const std::string message =
        testing::thrownMessage([&] { obstacleSolids(deformingScene(folder, 10.0)); });
    EXPECT_NE(message.find("[[obstacle]] #1"), std::string::npos) << message;
    EXPECT_NE(message.find("flag_0003.obj is missing"), std::string::npos) << message;
    // A folder in the file's place is named as such.
    std::filesystem::create_directory(sequenceFile(folder / "flag_####.obj", 3));
    const std::string folderMessage =
        testing::thrownMessage([&] { obstacleSolids(deformingScene(folder, 10.0)); });
    EXPECT_NE(folderMessage.find("flag_0003.obj is a directory, not an OBJ file"),
              std::string::npos)
        << folderMessage;
    std::filesystem::remove(sequenceFile(folder / "flag_####.obj", 3));
    // A shorter run needs files 1 and 2 alone.
    SceneSpec shorter = deformingScene(folder, 10.0);
    shorter.output.frames = 4;
    EXPECT_EQ(obstacleSolids(shorter).front().size(), 1u);
    // A file that is no closed surface is named with the obstacle.
    writeObj(sequenceFile(folder / "flag_####.obj", 3),
             TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}});
    const std::string open =
        testing::thrownMessage([&] { obstacleSolids(deformingScene(folder, 10.0)); });
    EXPECT_NE(open.find("[[obstacle]] #1"), std::string::npos) << open;
    EXPECT_NE(open.find("flag_0003.obj"), std::string::npos) << open;
}

}  // namespace
}  // namespace modeflow
