// Domain features beyond the analytic shapes: meshes, frequency-shaped mode ranges, no-slip walls.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "precompute/Precompute.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

BasisCache solve(const SceneSpec& scene) {
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

TEST(DomainVariants, MeshedSphereMatchesTheAnalyticBall) {
    // A finely tessellated sphere (radius 0.8) must give nearly the analytic ball's spectrum:
    // the mesh → level set → cut cell path loses only the tessellation error.
    const testing::TestFolder dir;
    writeObj(dir / "sphere.obj", makeIcosphere(4, 0.8));

    SceneSpec analytic = testing::gridScene({16, 16, 16}, {-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}, 3);
    analytic.domain = {testing::ball({0.0, 0.0, 0.0}, 0.8)};
    analytic.basis.velocityModes = {{1, 8}};
    analytic.basis.scalarModes = 0;
    SceneSpec meshed = analytic;
    meshed.domain[0].kind = ShapeKind::Mesh;
    meshed.domain[0].meshFile = dir / "sphere.obj";

    const BasisCache a = solve(analytic);
    const BasisCache m = solve(meshed);
    double worst = 0.0;
    for (int i = 0; i < 8; ++i)
        worst =
            std::max(worst, std::abs(m.velocity.eigenvalues[i] / a.velocity.eigenvalues[i] - 1.0));
    std::printf("meshed vs analytic ball, first 8 κ²: max relative difference %.2e\n", worst);
    EXPECT_LT(worst, 1e-2);
    testing::expectValidVelocityBasis(m);
}

TEST(DomainVariants, ModeRangesSelectFromTheFullSpectrum) {
    SceneSpec scene = testing::unitBallScene(2, 40, 12, 0);
    const BasisCache full = solve(scene);
    scene.basis.velocityModes = {{1, 3}, {9, 12}};
    const BasisCache shaped = solve(scene);
    ASSERT_EQ(shaped.velocity.eigenvalues.size(), 7);
    const std::vector<int> expected = {1, 2, 3, 9, 10, 11, 12};
    EXPECT_EQ(shaped.velocity.modeNumbers, expected);
    for (int i = 0; i < 7; ++i)
        EXPECT_NEAR(shaped.velocity.eigenvalues[i], full.velocity.eigenvalues[expected[i] - 1],
                    1e-9 * full.velocity.eigenvalues[expected[i] - 1]);
    testing::expectValidVelocityBasis(shaped);
}

TEST(DomainVariants, NoSlipWallsRaiseTheSpectrum) {
    // Keeping the wall vorticity penalizes tangential slip: every eigenvalue rises, and the disk's
    // first mode moves towards the no-slip (Stokes) value j₁,₁² = 14.68 from the free-slip
    // j₀,₁² = 5.78.
    SceneSpec scene = testing::unitBallScene(2, 64, 6, 0);
    const BasisCache freeSlip = solve(scene);
    scene.basis.wall = WallKind::NoSlip;
    const BasisCache noSlip = solve(scene);
    std::printf("disk first κ²: free-slip %.4f, no-slip %.4f\n", freeSlip.velocity.eigenvalues[0],
                noSlip.velocity.eigenvalues[0]);
    for (int i = 0; i < 6; ++i)
        EXPECT_GT(noSlip.velocity.eigenvalues[i], freeSlip.velocity.eigenvalues[i]) << i;
    EXPECT_GT(noSlip.velocity.eigenvalues[0], 10.0);
    testing::expectValidVelocityBasis(noSlip);
}

}  // namespace
}  // namespace modeflow
