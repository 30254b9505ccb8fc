/// Dye on a surface in its scalar basis (engine/surface/SurfaceDye): advection keeps the dye's
/// variance exactly, sources raise its mean at their rate times their share of the area, and a
/// solid rotation of the sphere turns each band of the dye rigidly at its angular speed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <iostream>

#include "engine/surface/SurfaceDye.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

BasisCache sphereBasis(const testing::TestFolder& folder, int subdivisions = 3,
                       int scalarModes = 35) {
    writeObj(folder / "sphere.obj", makeIcosphere(subdivisions));
    SceneSpec scene;
    scene.surface = SurfaceSpec{folder / "sphere.obj"};
    scene.basis.velocityModes = {{1, 8}};
    scene.basis.scalarModes = scalarModes;
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

SmokeEmitter northPole(double rate) {
    SmokeEmitter e;
    e.centre = {0.0, 0.0, 1.0};
    e.radius = 0.3;
    e.densityRate = rate;
    return e;
}

TEST(SurfaceDye, AdvectionKeepsTheVarianceAndSourcesRaiseTheMean) {
    testing::TestFolder folder;
    const BasisCache cache = sphereBasis(folder);
    const SmokeEmitter source = northPole(2.0);
    SurfaceDye dye(cache, std::span<const SmokeEmitter>(&source, 1));
    const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(8, -1.0, 1.0);
    for (int s = 0; s < 10; ++s) dye.step(v, v, 0.0, 0.05);
    // The mean: rate × the covered share of the area × time.
    double covered = 0.0, total = 0.0;
    for (std::size_t i = 0; i < cache.surface.mesh.vertices.size(); ++i) {
        total += cache.scalar.cellStar[Eigen::Index(i)];
        if (source.contains(cache.surface.mesh.vertices[i], 3))
            covered += cache.scalar.cellStar[Eigen::Index(i)];
    }
    EXPECT_NEAR(dye.state()[0], 2.0 * covered / total * 0.5, 1e-12);
    // Without sources the variance stays exactly.
    SurfaceDye carried(cache, {});
    carried.setState(dye.state());
    const double variance = carried.state().tail(35).squaredNorm();
    for (int s = 0; s < 200; ++s) carried.step(v, v * 0.9, 0.0, 0.05);
    EXPECT_NEAR(carried.state().tail(35).squaredNorm(), variance, 1e-12 * variance);
    EXPECT_GT((carried.state() - dye.state()).norm(), 1e-3 * dye.state().norm())
        << "the dye did not move";
}

/// Under a solid rotation at angular speed Ω, a band of degree l turns rigidly: the advection
/// operator A(v) has the eigenvalues ±i m Ω, m = 1..l, in each band (and 0).
TEST(SurfaceDye, ASolidRotationTurnsEachBandAtItsAngularSpeed) {
    testing::TestFolder folder;
    const BasisCache cache = sphereBasis(folder, 4, 15);  // l = 1..3
    Eigen::VectorXd v = Eigen::VectorXd::Zero(8);
    v.head(3) << 0.6, 0.2, -0.7;  // the l = 1 velocity modes: a rotation
    // Ω is the largest speed on the unit sphere (at the rotation's equator).
    const Eigen::VectorXd u = cache.surface.vertexVelocity * v;
    double omega = 0.0;
    for (Eigen::Index i = 0; i < u.size() / 3; ++i)
        omega = std::max(omega, u.segment<3>(3 * i).norm());
    const Eigen::VectorXd pairs = cache.surface.advection * v;
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(15, 15);
    for (int i = 0, at = 0; i < 15; ++i)
        for (int j = i + 1; j < 15; ++j, ++at) k(i, j) = pairs[at], k(j, i) = -pairs[at];
    EXPECT_EQ((k + k.transpose()).norm(), 0.0);
    std::vector<double> turns;
    const Eigen::VectorXcd lambdas = Eigen::EigenSolver<Eigen::MatrixXd>(k).eigenvalues();
    for (const auto& lambda : lambdas)
        if (lambda.imag() > 1e-6 * omega) turns.push_back(lambda.imag() / omega);
    std::sort(turns.begin(), turns.end());
    const std::vector<double> expected{1, 1, 1, 2, 2, 3};
    ASSERT_EQ(turns.size(), expected.size());
    for (std::size_t i = 0; i < turns.size(); ++i) {
        std::cout << "turn rate " << turns[i] << " Ω (exact " << expected[i] << " Ω)\n";
        EXPECT_NEAR(turns[i], expected[i], 0.03 * expected[i]);
    }
}

}  // namespace
}  // namespace modeflow
