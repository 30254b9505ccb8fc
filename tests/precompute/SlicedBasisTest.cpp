// `[basis] eigensolver`: spectrum slicing (SLEPc) and shift-invert Lanczos (Spectra) give the same
// bases on curved domains: the same eigenvalues and the same span for every group of (nearly)
// equal eigenvalues, harmonic fields, frequency-shaping ranges and scalar bases included.

#include <gtest/gtest.h>

#include "precompute/Precompute.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

BasisCache solveWith(SceneSpec scene, EigensolverChoice choice) {
    scene.basis.eigensolver = choice;
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

/// Largest relative eigenvalue difference (harmonic ones, exactly 0 in both, compare as equal).
double eigenvalueDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    double worst = 0.0;
    for (Eigen::Index i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) worst = std::max(worst, std::abs(a[i] - b[i]) / std::abs(b[i]));
    return worst;
}

/// Largest distance ‖B_g − A_g A_gᵀ M B_g‖ between the columns of each group g of eigenvalues
/// closer than 1e-3 relative (a degenerate eigenspace holds any orthonormal basis of itself, and
/// nearly degenerate vectors turn into each other with round-off), M-orthonormal columns.
double spanDifference(const Eigen::VectorXd& values, const Eigen::MatrixXd& a,
                      const Eigen::MatrixXd& b, const Eigen::VectorXd& mass) {
    double worst = 0.0;
    for (Eigen::Index first = 0; first < values.size();) {
        Eigen::Index end = first + 1;
        while (end < values.size() && values[end] - values[end - 1] <= 1e-3 * values[end]) ++end;
        const Eigen::MatrixXd ag = a.middleCols(first, end - first);
        const Eigen::MatrixXd bg = b.middleCols(first, end - first);
        const Eigen::MatrixXd rest = bg - ag * (ag.transpose() * mass.asDiagonal() * bg);
        worst = std::max(worst, rest.cwiseAbs().maxCoeff() / bg.cwiseAbs().maxCoeff());
        first = end;
    }
    return worst;
}

void expectSameBases(const SceneSpec& scene) {
    const BasisCache spectra = solveWith(scene, EigensolverChoice::Spectra);
    const BasisCache sliced = solveWith(scene, EigensolverChoice::Slepc);
    testing::expectValidVelocityBasis(sliced);
    EXPECT_EQ(sliced.velocity.modeNumbers, spectra.velocity.modeNumbers);
    EXPECT_EQ(sliced.velocity.harmonic, spectra.velocity.harmonic);
    EXPECT_LE(eigenvalueDifference(sliced.velocity.eigenvalues, spectra.velocity.eigenvalues), 1e-9)
        << "velocity eigenvalues";
    EXPECT_LE(spanDifference(spectra.velocity.eigenvalues, spectra.velocity.modes,
                             sliced.velocity.modes, spectra.faceStar),
              1e-7)
        << "velocity spans";
    EXPECT_LE(eigenvalueDifference(sliced.scalar.eigenvalues, spectra.scalar.eigenvalues), 1e-9)
        << "scalar eigenvalues";
    EXPECT_LE(spanDifference(spectra.scalar.eigenvalues, spectra.scalar.modes, sliced.scalar.modes,
                             spectra.scalar.cellStar),
              1e-7)
        << "scalar spans";
}

TEST(SlicedBasis, DiskSameAsLanczos) {
    expectSameBases(testing::unitBallScene(2, 48, 40, 20));
}

TEST(SlicedBasis, AnnulusWithHarmonicFieldSameAsLanczos) {
    SceneSpec scene = testing::unitBallScene(2, 64, 35, 13);
    scene.domain.push_back(testing::ball({0.0, 0.0, 0.0}, 0.4, CsgOp::Subtract));
    scene.basis.scalarBoundary = ScalarBoundary::Dirichlet;
    expectSameBases(scene);
}

TEST(SlicedBasis, BallFrequencyRangesSameAsLanczos) {
    // The counts and ranges end where a group of nearly equal eigenvalues does: a cut through one
    // keeps an arbitrary part of it.
    SceneSpec scene = testing::unitBallScene(3, 16, 0, 9);
    scene.domain = {testing::ball({0.03, 0.02, 0.01}, 1.0)};
    scene.basis.velocityModes = {{1, 11}, {33, 42}};
    expectSameBases(scene);
}

TEST(SlicedBasis, SolidTorusWithHarmonicFieldSameAsLanczos) {
    SceneSpec scene = testing::gridScene({28, 28, 14}, {-1.0, -1.0, -0.5}, {1.0, 1.0, 0.5}, 3);
    scene.domain = {testing::torus({0.0, 0.0, 0.0}, 0.6, 0.3)};
    scene.basis.velocityModes = {{1, 20}};
    scene.basis.scalarModes = 4;
    expectSameBases(scene);
}

}  // namespace
}  // namespace modeflow
