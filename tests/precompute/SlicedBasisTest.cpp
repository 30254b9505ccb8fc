// `[basis] eigensolver`: spectrum slicing (SLEPc), block Lanczos and shift-invert Lanczos (Spectra)
// give the same bases on curved domains: the same eigenvalues and the same span for every group of
// (nearly) equal eigenvalues, harmonic fields, frequency-shaping ranges and scalar bases included.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "precompute/Precompute.h"
#include "tests/support/BasisComparison.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

BasisCache solveWith(SceneSpec scene, EigensolverChoice choice) {
    scene.basis.eigensolver = choice;
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

/// The modes of an eigenvalue apart from the others (by 1e-3 of the largest) are the same vectors,
/// signs included: each solver's are turned so that their first entry of largest magnitude is
/// positive (precompute/solve/SpectralBasis.h). Returns how many were compared.
int expectSameIsolatedModes(const Eigen::VectorXd& values, const Eigen::MatrixXd& expected,
                            const Eigen::MatrixXd& modes, const Eigen::VectorXd& star) {
    const double gap = 1e-3 * values.cwiseAbs().maxCoeff();
    int compared = 0;
    for (Eigen::Index i = 0; i < values.size(); ++i) {
        bool isolated = true;
        for (Eigen::Index j = 0; j < values.size(); ++j)
            isolated = isolated && (j == i || std::abs(values[j] - values[i]) >= gap);
        if (!isolated) continue;
        const Eigen::VectorXd d = modes.col(i) - expected.col(i);
        EXPECT_LE(std::sqrt(d.dot(star.asDiagonal() * d)), 1e-5) << "mode " << i + 1;
        ++compared;
    }
    return compared;
}

/// Returns how many velocity modes were compared as vectors.
int expectSameBases(const BasisCache& spectra, const BasisCache& other, const char* name) {
    SCOPED_TRACE(name);
    testing::expectValidVelocityBasis(other);
    EXPECT_EQ(other.velocity.modeNumbers, spectra.velocity.modeNumbers);
    EXPECT_EQ(other.velocity.harmonic, spectra.velocity.harmonic);
    EXPECT_LE(
        testing::eigenvalueDifference(other.velocity.eigenvalues, spectra.velocity.eigenvalues),
        1e-9)
        << "velocity eigenvalues";
    EXPECT_LE(testing::spanDifference(spectra.velocity.eigenvalues, spectra.velocity.modes,
                                      other.velocity.modes, spectra.faceStar),
              1e-7)
        << "velocity spans";
    const int compared =
        expectSameIsolatedModes(spectra.velocity.eigenvalues, spectra.velocity.modes,
                                other.velocity.modes, spectra.faceStar);
    EXPECT_LE(testing::eigenvalueDifference(other.scalar.eigenvalues, spectra.scalar.eigenvalues),
              1e-9)
        << "scalar eigenvalues";
    EXPECT_LE(testing::spanDifference(spectra.scalar.eigenvalues, spectra.scalar.modes,
                                      other.scalar.modes, spectra.scalar.cellStar),
              1e-7)
        << "scalar spans";
    if (spectra.scalar.eigenvalues.size() > 0)  // a torus's scalar eigenvalues come in pairs
        expectSameIsolatedModes(spectra.scalar.eigenvalues, spectra.scalar.modes,
                                other.scalar.modes, spectra.scalar.cellStar);
    return compared;
}

/// Slicing and block Lanczos against Spectra's Lanczos. Returns the fewest velocity modes compared
/// as vectors (a ball's are all degenerate).
int expectSameBases(const SceneSpec& scene) {
    const BasisCache spectra = solveWith(scene, EigensolverChoice::Spectra);
    const int sliced =
        expectSameBases(spectra, solveWith(scene, EigensolverChoice::Slepc), "sliced");
    const int block =
        expectSameBases(spectra, solveWith(scene, EigensolverChoice::Block), "block Lanczos");
    return std::min(sliced, block);
}

TEST(SlicedBasis, DiskSameAsLanczos) {
    EXPECT_GT(expectSameBases(testing::unitBallScene(2, 48, 40, 20)), 5);
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

TEST(SlicedBasis, CentredBallEveryCopyOfADegenerateEigenvalueFound) {
    // The cube's symmetries make eigenvalues of the centred ball's operators exactly equal in
    // pairs and triples; one Lanczos run found one copy of the 19th scalar eigenvalue and skipped
    // the other (30.7448), which slicing, counting by inertia, cannot.
    expectSameBases(testing::unitBallScene(3, 16, 3, 20));
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
