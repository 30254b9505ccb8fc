/// @file MovingObstacleTest.cpp
/// Moving obstacles' CPU reference (engine/simulation/MovingObstacle): key-framed paths and
/// rotations, shapes, and the seed's §6.3.5 correction, which must shrink the normal-velocity
/// mismatch on covered faces and make still fluid move with the solid, turning with a paddle.

#include <cmath>
#include <fstream>
#include <iostream>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/reference/ObstacleCorrection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestFolder.h"
#include "tests/support/ThrownMessage.h"
#include "tools/compose/MeshSolids.h"

namespace modeflow {
namespace {

/// A walled grid of the given dimension (covers() reads its dimension and periodic axes).
MacGrid walledGrid(int dim) {
    MacGrid grid;
    grid.dim = dim;
    return grid;
}

/// A pose at `centre`, not turned, still.
ObstaclePose at(const Vec3& centre) {
    ObstaclePose pose;
    pose.centre = centre;
    return pose;
}

MovingObstacle ball(double radius, std::vector<std::pair<double, Vec3>> path) {
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Ball;
    spec.radius = radius;
    spec.path = std::move(path);
    return {spec};
}

/// Σ over DOF faces of ⋆·(area·m)²: the ⋆-norm² of a face field's fluxes.
double starNorm2(const BasisCache& cache, const std::vector<double>& faceField) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    double sum = 0.0;
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const double flux = faceField[std::size_t(cache.faces[d])] *
                            grid.faceArea(locateFace(grid, cache.faces[d]).axis);
        sum += cache.faceStar[Eigen::Index(d)] * flux * flux;
    }
    return sum;
}

TEST(MovingObstacle, FollowsItsKeyFramesLinearly) {
    const MovingObstacle o = ball(0.1, {{1.0, {0.0, 0.0, 0.0}}, {3.0, {1.0, -2.0, 0.0}}});
    EXPECT_EQ(o.centreAt(0.0), (Vec3{0.0, 0.0, 0.0}));  // holds before the first frame
    EXPECT_EQ(o.centreAt(2.0), (Vec3{0.5, -1.0, 0.0}));
    EXPECT_EQ(o.centreAt(9.0), (Vec3{1.0, -2.0, 0.0}));  // and after the last
    EXPECT_EQ(o.velocityAt(2.0), (Vec3{0.5, -1.0, 0.0}));
    EXPECT_EQ(o.velocityAt(0.5), (Vec3{0.0, 0.0, 0.0}));
    EXPECT_EQ(o.velocityAt(3.5), (Vec3{0.0, 0.0, 0.0}));
}

TEST(MovingObstacle, ShapesCoverWhatTheySay) {
    ObstacleSpec box;
    box.shape = ObstacleShape::Box;
    box.halfSize = {0.2, 0.1, 0.3};
    box.path = {{0.0, {0.0, 0.0, 0.0}}};
    const MovingObstacle b{box};
    EXPECT_TRUE(b.covers({0.19, -0.09, 0.0}, at({0.0, 0.0, 0.0}), walledGrid(2)));
    EXPECT_FALSE(b.covers({0.21, 0.0, 0.0}, at({0.0, 0.0, 0.0}), walledGrid(2)));
    EXPECT_FALSE(b.covers({0.0, 0.0, 0.31}, at({0.0, 0.0, 0.0}), walledGrid(3)));
    ObstacleSpec capsule;
    capsule.shape = ObstacleShape::Capsule;
    capsule.radius = 0.1;
    capsule.axis = {0.5, 0.0, 0.0};
    capsule.path = box.path;
    const MovingObstacle c{capsule};
    EXPECT_TRUE(
        c.covers({0.55, 0.05, 0.0}, at({0.0, 0.0, 0.0}), walledGrid(2)));  // near the end cap
    EXPECT_FALSE(c.covers({0.65, 0.0, 0.0}, at({0.0, 0.0, 0.0}), walledGrid(2)));  // past it
    EXPECT_FALSE(
        c.covers({0.0, 0.11, 0.0}, at({0.0, 0.0, 0.0}), walledGrid(2)));  // beside the segment
}

TEST(MovingObstacle, CoversAcrossAPeriodicSeamAtTheMinimumImage) {
    // [0, 2] × [0, 1], periodic along x: a ball at x = 1.95 reaches over the seam to x = 0.1.
    MacGrid grid = walledGrid(2);
    grid.cells = {20, 10, 1};
    grid.spacing = {0.1, 0.1, 1.0};
    ObstacleSpec ball;
    ball.shape = ObstacleShape::Ball;
    ball.radius = 0.2;
    ball.path = {{0.0, {1.95, 0.5, 0.0}}};
    const MovingObstacle o{ball};
    EXPECT_FALSE(o.covers({0.1, 0.5, 0.0}, at({1.95, 0.5, 0.0}), grid)) << "walled";
    grid.periodic[0] = true;
    EXPECT_TRUE(o.covers({0.1, 0.5, 0.0}, at({1.95, 0.5, 0.0}), grid))
        << "periodic: 0.15 away across the seam";
    EXPECT_FALSE(o.covers({0.3, 0.5, 0.0}, at({1.95, 0.5, 0.0}), grid))
        << "periodic: 0.35 away across the seam";
    EXPECT_TRUE(o.covers({1.8, 0.5, 0.0}, at({1.95, 0.5, 0.0}), grid))
        << "periodic: on its own side";
}

TEST(MovingObstacle, AnObstacleCrossingAPeriodicSeamDragsTheFluidAtBothEnds) {
    // The channel around a disk, periodic along x over [0, 2]: a ball moving along +x at speed
    // 0.4 is on the seam at t = 0.5 (its centre at x = 2, i.e. 0). It covers faces at both ends,
    // and the fluid it drags moves along +x at both.
    const BasisCache& cache = testing::periodicChannel2d();
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const std::vector<MovingObstacle> obstacles{
        ball(0.15, {{0.0, {1.8, 0.5, 0.0}}, {1.0, {2.2, 0.5, 0.0}}})};
    const std::vector<double> still(std::size_t(grid.faceTotal()), 0.0);
    const std::vector<double> mismatch = reference::obstacleMismatch(cache, still, obstacles, 0.5);
    int left = 0, right = 0;
    for (std::int64_t f = 0; f < grid.faceCount(0); ++f)
        if (mismatch[std::size_t(f)] != 0.0) {
            EXPECT_DOUBLE_EQ(mismatch[std::size_t(f)], -0.4) << "face " << f;
            (faceCentre(grid, locateFace(grid, f))[0] < 1.0 ? left : right) += 1;
        }
    EXPECT_GT(left, 3) << "covered x-faces near x = 0";
    EXPECT_GT(right, 3) << "covered x-faces near x = 2";
    const std::vector<double> u = reference::reconstructFaceField(
        cache, -reference::obstacleCorrection(cache, still, obstacles, 0.5));
    const double atSeam = u[std::size_t(grid.faceIndex(0, 0, 8, 0))];
    const double before = u[std::size_t(grid.faceIndex(0, 31, 8, 0))];
    const double after = u[std::size_t(grid.faceIndex(0, 1, 8, 0))];
    std::cout << "fluid x velocity at the seam under the ball " << atSeam << ", a cell before "
              << before << ", a cell after " << after << " (ball: 0.4)\n";
    EXPECT_GT(atSeam, 0.05);
    EXPECT_GT(before, 0.5 * atSeam);
    EXPECT_GT(after, 0.5 * atSeam);
}

TEST(MovingObstacle, CorrectionShrinksTheMismatchOfAStillObstacle) {
    const BasisCache& cache = testing::disk2d();
    RandomVelocitySpec random;
    const Eigen::VectorXd v = randomVelocity(int(cache.velocity.modes.cols()), random);
    const std::vector<MovingObstacle> obstacles{ball(0.35, {{0.0, {0.2, 0.1, 0.0}}})};
    const std::vector<double> before = reference::reconstructFaceField(cache, v);
    const Eigen::VectorXd corrected =
        v - reference::obstacleCorrection(cache, before, obstacles, 0.0);
    const std::vector<double> after = reference::reconstructFaceField(cache, corrected);
    const double m0 = starNorm2(cache, reference::obstacleMismatch(cache, before, obstacles, 0.0));
    const double m1 = starNorm2(cache, reference::obstacleMismatch(cache, after, obstacles, 0.0));
    std::cout << "still ball: covered-face mismatch (⋆-norm²) " << m0 << " -> " << m1 << "\n";
    EXPECT_GT(m0, 0.0);
    EXPECT_LT(m1, 0.8 * m0);  // a least-squares step in a 20-mode basis: ‖m'‖² ≤ ‖m‖² − ‖Pm‖²
}

TEST(MovingObstacle, AMovingObstacleDragsStillFluidAlong) {
    const BasisCache& cache = testing::disk2d();
    const std::vector<MovingObstacle> obstacles{
        ball(0.3, {{0.0, {-0.3, 0.0, 0.0}}, {1.0, {0.3, 0.0, 0.0}}})};
    const std::vector<double> still(std::size_t(MacGrid::fromSpec(cache.grid).faceTotal()), 0.0);
    const Eigen::VectorXd v = -reference::obstacleCorrection(cache, still, obstacles, 0.5);
    ASSERT_GT(v.norm(), 0.0);
    const std::vector<double> u = reference::reconstructFaceField(cache, v);
    // The fluid at the obstacle's centre moves along +x, as the obstacle does (speed 0.6).
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const double centreX = u[std::size_t(grid.faceIndex(0, 16, 16, 0))];
    std::cout << "fluid x velocity at the moving ball's centre: " << centreX << " (ball: 0.6)\n";
    EXPECT_GT(centreX, 0.1);
}

/// A thin box (a paddle) still at the origin, turning about z at `degreesPerSecond`.
MovingObstacle paddle(double degreesPerSecond) {
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Box;
    spec.halfSize = {0.5, 0.08, 0.0};
    spec.path = {{0.0, {0.0, 0.0, 0.0}}};
    spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {10.0, {0.0, 0.0, 1.0}, 10.0 * degreesPerSecond}};
    return {spec};
}

TEST(MovingObstacle, TurnsAlongItsRotationKeyFrames) {
    const MovingObstacle fan = paddle(360.0);  // one turn a second for 10 s
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
    EXPECT_TRUE((fan.orientationAt(-1.0) * x).isApprox(x)) << "held before the first key frame";
    EXPECT_TRUE((fan.orientationAt(0.5) * x).isApprox(-x, 1e-12)) << "half a turn";
    EXPECT_TRUE((fan.orientationAt(0.25) * x).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
    EXPECT_TRUE((fan.orientationAt(7.0) * x).isApprox(x, 1e-12))
        << "whole turns, not the short way";
    EXPECT_NEAR(fan.angularVelocityAt(3.3)[2], 2.0 * M_PI, 1e-12);
    EXPECT_EQ(fan.angularVelocityAt(10.0), (Vec3{0.0, 0.0, 0.0})) << "still after the last";
    // Between key frames about different axes: the slerp, about the axis of the turn between.
    ObstacleSpec spec = fan.spec;
    spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {1.0, {1.0, 0.0, 0.0}, 90.0}};
    const MovingObstacle tilt{spec};
    const Eigen::Vector3d y = tilt.orientationAt(0.5) * Eigen::Vector3d::UnitY();
    EXPECT_TRUE(y.isApprox(Eigen::Vector3d(0.0, std::sqrt(0.5), std::sqrt(0.5)), 1e-12)) << y;
    const Vec3 w = tilt.angularVelocityAt(0.5);
    EXPECT_NEAR(w[0], 0.5 * M_PI, 1e-12);
    EXPECT_NEAR(std::hypot(w[1], w[2]), 0.0, 1e-12);
}

TEST(MovingObstacle, ATurnedBoxCoversWhatItsOwnFrameHolds) {
    const MovingObstacle fan = paddle(360.0);
    const MacGrid grid = walledGrid(2);
    ObstaclePose pose = fan.poseAt(0.25);  // a quarter turn: the paddle lies along y
    EXPECT_TRUE(fan.covers({0.02, 0.45, 0.0}, pose, grid));
    EXPECT_FALSE(fan.covers({0.45, 0.02, 0.0}, pose, grid));
    pose = fan.poseAt(0.0);
    EXPECT_TRUE(fan.covers({0.45, 0.02, 0.0}, pose, grid));
    EXPECT_FALSE(fan.covers({0.02, 0.45, 0.0}, pose, grid));
    // Its material moves with the spin: v + ω × r, 2π · 0.4 along y at r = (0.4, 0).
    const Vec3 u = fan.velocityOf({0.4, 0.0, 0.0}, pose, grid);
    EXPECT_NEAR(u[0], 0.0, 1e-12);
    EXPECT_NEAR(u[1], 2.0 * M_PI * 0.4, 1e-12);
}

/// The fluid's angular momentum about the z axis through the origin, Σ area · (x u_y − y u_x)
/// over the DOF faces.
double angularMomentum(const BasisCache& cache, const std::vector<double>& u) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    double sum = 0.0;
    for (const std::int64_t face : cache.faces) {
        const FaceLocation location = locateFace(grid, face);
        const Vec3 x = faceCentre(grid, location);
        const double arm = location.axis == 0 ? -x[1] : x[0];
        sum += grid.faceArea(location.axis) * arm * u[std::size_t(face)];
    }
    return sum;
}

/// Still fluid in the disk with `paddle` (turning at `speed` °/s) in it: the correction makes it
/// move with the paddle, so its angular momentum takes the paddle's sign, and grows while the
/// paddle keeps turning (the correction applied again each step, the fluid keeping what it was
/// given).
void expectTurnsStillFluidItsWay(const MovingObstacle& paddle, double speed) {
    const BasisCache& cache = testing::disk2d();
    const std::vector<MovingObstacle> obstacles{paddle};
    Eigen::VectorXd v = Eigen::VectorXd::Zero(cache.velocity.modes.cols());
    double previous = 0.0;
    for (int step = 0; step < 4; ++step) {
        v -= reference::obstacleCorrection(cache, reference::reconstructFaceField(cache, v),
                                           obstacles, 0.1 * step);
        const double l = angularMomentum(cache, reference::reconstructFaceField(cache, v));
        std::cout << "paddle at " << speed << "°/s, step " << step << ": fluid angular momentum "
                  << l << "\n";
        EXPECT_GT(l * speed, 0.0) << "the fluid turns the paddle's way";
        EXPECT_GT(std::abs(l), std::abs(previous)) << "and more while it keeps turning";
        previous = l;
    }
}

TEST(MovingObstacle, ATurningPaddleTurnsStillFluidItsWay) {
    for (const double speed : {90.0, -90.0}) expectTurnsStillFluidItsWay(paddle(speed), speed);
}

// ---- mesh obstacles ------------------------------------------------------------------------

/// A mesh obstacle of `mesh` (written to `folder`) at `scale`, on `path`, with its level set
/// built as a run builds it, for a scene on `cache`'s grid.
MovingObstacle meshObstacle(const testing::TestFolder& folder, const TriangleMesh& mesh,
                            double scale, std::vector<std::pair<double, Vec3>> path,
                            const BasisCache& cache) {
    SceneSpec scene;
    scene.sourceFile = folder / "s.toml";
    scene.grid = cache.grid;
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Mesh;
    spec.meshFile = folder / "mesh.obj";
    spec.scale = scale;
    spec.path = std::move(path);
    writeObj(spec.meshFile, mesh);
    scene.obstacles = {spec};
    MovingObstacle obstacle{spec};
    obstacle.levelSet = obstacleSolids(scene).front().front();
    return obstacle;
}

TEST(MovingObstacle, AMeshIcosphereBehavesAsTheBallOnItsPath) {
    // A unit icosphere at scale 0.3 against the analytic ball of radius 0.3 on the disk's 32²
    // grid (the 2D obstacle is the section by z = 0), moving across the disk.
    const testing::TestFolder folder;
    const BasisCache& cache = testing::disk2d();
    const std::vector<std::pair<double, Vec3>> path{{0.0, {-0.3, 0.1, 0.0}},
                                                    {1.0, {0.3, -0.1, 0.0}}};
    const std::vector<MovingObstacle> mesh{
        meshObstacle(folder, makeIcosphere(3), 0.3, path, cache)};
    const std::vector<MovingObstacle> analytic{ball(0.3, path)};
    RandomVelocitySpec random;
    const Eigen::VectorXd v = randomVelocity(int(cache.velocity.modes.cols()), random);
    const std::vector<double> faces = reference::reconstructFaceField(cache, v);
    for (const double t : {0.0, 0.37, 1.0}) {
        const std::vector<double> m = reference::obstacleMismatch(cache, faces, mesh, t),
                                  b = reference::obstacleMismatch(cache, faces, analytic, t);
        int covered = 0, differ = 0;
        for (std::size_t f = 0; f < m.size(); ++f) {
            covered += b[f] != 0.0;
            differ += (m[f] != 0.0) != (b[f] != 0.0);
        }
        const Eigen::VectorXd dm = reference::obstacleCorrection(cache, faces, mesh, t),
                              db = reference::obstacleCorrection(cache, faces, analytic, t);
        const double relative = (dm - db).norm() / db.norm();
        std::cout << "t = " << t << ": the ball covers " << covered
                  << " faces, the mesh differs on " << differ << "; corrections differ by "
                  << relative << " (relative)\n";
        EXPECT_GT(covered, 50);
        EXPECT_LE(differ, covered / 25) << "coverage within the discretization";
        EXPECT_LE(relative, 0.05);
    }
}

TEST(MovingObstacle, ATurningPaddleMeshTurnsStillFluidItsWay) {
    // A slab of six cubes, 0.96 × 0.16 × 0.16 at scale 0.16, turning about z at the origin.
    const testing::TestFolder folder;
    const BasisCache& cache = testing::disk2d();
    const TriangleMesh slab = makeVoxelSurface(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}}, 1, 0.16);
    for (const double speed : {90.0, -90.0}) {
        MovingObstacle paddle = meshObstacle(folder, slab, 1.0, {{0.0, {0.0, 0.0, 0.0}}}, cache);
        paddle.spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {10.0, {0.0, 0.0, 1.0}, 10.0 * speed}};
        expectTurnsStillFluidItsWay(paddle, speed);
    }
}

/// What obstacleSolids says of the mesh `text` in a scene on the disk's grid (2D).
std::string meshRefusal(const std::string& text, double scale = 1.0) {
    const testing::TestFolder folder;
    SceneSpec scene;
    scene.sourceFile = folder / "s.toml";
    scene.grid = testing::disk2d().grid;
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Mesh;
    spec.meshFile = folder / "m.obj";
    spec.scale = scale;
    spec.path = {{0.0, {0.0, 0.0, 0.0}}};
    std::ofstream(spec.meshFile) << text;
    scene.obstacles = {ball(0.1, spec.path).spec, spec};
    return testing::thrownMessage([&] { obstacleSolids(scene); });
}

TEST(MovingObstacle, BadObstacleMeshesAreRefusedNamingTheObstacle) {
    // Outward tetrahedra: one crossing z = 0, one above it.
    const std::string faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    EXPECT_EQ(meshRefusal("v -0.3 -0.3 -0.3\nv 0.6 -0.3 -0.3\nv -0.3 0.6 -0.3\nv -0.3 -0.3 0.6\n" +
                          faces),
              "");
    std::string what = meshRefusal("v 0 0 0.1\nv 0.5 0 0.1\nv 0 0.5 0.1\nv 0 0 0.6\n" + faces);
    EXPECT_NE(what.find("[[obstacle]] #2"), std::string::npos) << what;
    EXPECT_NE(what.find("does not cross that plane"), std::string::npos) << what;
    what = meshRefusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
    EXPECT_NE(what.find("[[obstacle]] #2"), std::string::npos) << what;
    EXPECT_NE(what.find("is inside out"), std::string::npos) << what;
    what = meshRefusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(what.find("belongs to no other triangle"), std::string::npos) << what;
    what = meshRefusal(
        "v -0.3 -0.3 -0.3\nv 0.6 -0.3 -0.3\nv -0.3 0.6 -0.3\nv -0.3 -0.3 0.6\n" + faces, 1e6);
    EXPECT_NE(what.find("far larger than the grid"), std::string::npos) << what;
    // Without its level set a mesh obstacle is refused, not taken for empty.
    ObstacleSpec bare;
    bare.shape = ObstacleShape::Mesh;
    bare.meshFile = "m.obj";
    bare.path = {{0.0, {0.0, 0.0, 0.0}}};
    const std::vector<MovingObstacle> obstacles{MovingObstacle{bare}};
    const std::vector<double> still(
        std::size_t(MacGrid::fromSpec(testing::disk2d().grid).faceTotal()), 0.0);
    EXPECT_THROW(reference::obstacleMismatch(testing::disk2d(), still, obstacles, 0.0), Error);
}

}  // namespace
}  // namespace modeflow
