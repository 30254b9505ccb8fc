// Harmonic velocity fields (κ = 0) count the domain's tunnels: exactly one for an annulus and for
// a solid torus, none for a disk. Their κ² is stored as exactly 0, not the solve's round-off.

#include <gtest/gtest.h>

#include "precompute/Precompute.h"
#include "precompute/solve/SpectralBasis.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

BasisCache solve(SceneSpec scene) {
    scene.basis.velocityModes = {{1, 6}};
    scene.basis.scalarModes = 0;
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

void expectOneHarmonic(const BasisCache& cache) {
    EXPECT_EQ(cache.velocity.harmonic, 1);
    EXPECT_EQ(cache.velocity.eigenvalues[0], 0.0) << "the solve's round-off is not cleared";
    EXPECT_GT(cache.velocity.eigenvalues[1], 1.0) << "second mode must not be harmonic";
    testing::expectValidVelocityBasis(cache);
}

TEST(HarmonicModes, AnnulusHasExactlyOne) {
    SceneSpec scene = testing::unitBallScene(2, 64);
    scene.domain.push_back(testing::ball({0.0, 0.0, 0.0}, 0.4, CsgOp::Subtract));
    expectOneHarmonic(solve(scene));
}

TEST(HarmonicModes, DiskHasNone) {
    SceneSpec scene = testing::unitBallScene(2, 48);
    EXPECT_EQ(solve(scene).velocity.harmonic, 0);
}

TEST(HarmonicModes, SolidTorusHasExactlyOne) {
    SceneSpec scene = testing::gridScene({28, 28, 14}, {-1.0, -1.0, -0.5}, {1.0, 1.0, 0.5}, 3);
    scene.domain = {testing::torus({0.0, 0.0, 0.0}, 0.6, 0.3)};
    expectOneHarmonic(solve(scene));
}

}  // namespace
}  // namespace modeflow
