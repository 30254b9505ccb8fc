/// @file MovingObstacleTest.cpp
/// Moving obstacles' CPU reference (engine/reference/MovingObstacle): key-framed paths, shapes, and
/// the seed's §6.3.5 correction, which must shrink the normal-velocity mismatch on covered faces.

#include <cmath>

#include <gtest/gtest.h>

#include "engine/dynamics/InitialConditions.h"
#include "engine/core/FaceLocation.h"
#include "engine/reference/ObstacleCorrection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "tests/support/RealBases.h"

namespace modeflow {
namespace {

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
        const double flux = faceField[std::size_t(cache.faces[d])] * grid.faceArea(locateFace(grid, cache.faces[d]).axis);
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
    EXPECT_TRUE(b.covers({0.19, -0.09, 0.0}, {0.0, 0.0, 0.0}, 2));
    EXPECT_FALSE(b.covers({0.21, 0.0, 0.0}, {0.0, 0.0, 0.0}, 2));
    EXPECT_FALSE(b.covers({0.0, 0.0, 0.31}, {0.0, 0.0, 0.0}, 3));
    ObstacleSpec capsule;
    capsule.shape = ObstacleShape::Capsule;
    capsule.radius = 0.1;
    capsule.axis = {0.5, 0.0, 0.0};
    capsule.path = box.path;
    const MovingObstacle c{capsule};
    EXPECT_TRUE(c.covers({0.55, 0.05, 0.0}, {0.0, 0.0, 0.0}, 2));   // near the end cap
    EXPECT_FALSE(c.covers({0.65, 0.0, 0.0}, {0.0, 0.0, 0.0}, 2));   // past it
    EXPECT_FALSE(c.covers({0.0, 0.11, 0.0}, {0.0, 0.0, 0.0}, 2));   // beside the segment
}

TEST(MovingObstacle, CorrectionShrinksTheMismatchOfAStillObstacle) {
    const BasisCache& cache = testing::disk2d();
    RandomVelocitySpec random;
    const Eigen::VectorXd v = randomVelocity(int(cache.velocity.modes.cols()), random);
    const std::vector<MovingObstacle> obstacles{ball(0.35, {{0.0, {0.2, 0.1, 0.0}}})};
    const std::vector<double> before = reference::reconstructFaceField(cache, v);
    const Eigen::VectorXd corrected = v - reference::obstacleCorrection(cache, before, obstacles, 0.0);
    const std::vector<double> after = reference::reconstructFaceField(cache, corrected);
    const double m0 = starNorm2(cache, reference::obstacleMismatch(cache, before, obstacles, 0.0));
    const double m1 = starNorm2(cache, reference::obstacleMismatch(cache, after, obstacles, 0.0));
    std::cout << "still ball: covered-face mismatch (⋆-norm²) " << m0 << " -> " << m1 << "\n";
    EXPECT_GT(m0, 0.0);
    EXPECT_LT(m1, 0.8 * m0);  // a least-squares step in a 20-mode basis: ‖m'‖² ≤ ‖m‖² − ‖Pm‖²
}

TEST(MovingObstacle, AMovingObstacleDragsStillFluidAlong) {
    const BasisCache& cache = testing::disk2d();
    const std::vector<MovingObstacle> obstacles{ball(0.3, {{0.0, {-0.3, 0.0, 0.0}}, {1.0, {0.3, 0.0, 0.0}}})};
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

}  // namespace
}  // namespace modeflow
