// Periodic axes in the precompute: the wrapped complex reproduces the discrete spectra of tori and
// channels exactly, finds their harmonic fields (uniform flows along periodic axes, plus the
// circulations around holes that the topology leaves free), and refuses domains that do not
// repeat across a seam. Convergence around a disk in a periodic channel:
// PeriodicConvergenceSlowTest.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/core/Error.h"
#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// The 1D eigenvalue of mode l along an axis: 4/h² sin²(πl/n) on a periodic axis (l ∈ [0, n)),
/// 4/h² sin²(πl/2n) between walls.
double axisEigenvalue(const GridSpec& g, int axis, int l) {
    const int n = g.resolution[axis];
    const double s = std::sin(g.isPeriodic(axis) ? M_PI * l / n : M_PI * l / (2.0 * n));
    return 4.0 / (g.spacing(axis) * g.spacing(axis)) * s * s;
}

enum class Field { Velocity, Neumann, Dirichlet };

/// Sorted discrete spectrum of a box with periodic and walled axes. Wave vectors l ∈ [0, n) per
/// axis (Dirichlet walls: [1, n]). Velocity: component a exists at l when axis a is periodic or
/// l_a ≥ 1 (the normal component between walls is a sine); the divergence removes one of them
/// unless l = 0, so l carries (components − [l ≠ 0]) divergence-free fields, and l = 0 one
/// harmonic field per periodic axis. Neumann: every l but the constant.
std::vector<double> boxSpectrum(const GridSpec& g, Field field) {
    std::array<int, 3> lo{0, 0, 0}, hi{1, 1, 1};
    for (int a = 0; a < g.dim; ++a) {
        const bool shifted = field == Field::Dirichlet && !g.isPeriodic(a);
        lo[a] = shifted ? 1 : 0;
        hi[a] = g.resolution[a] + (shifted ? 1 : 0);
    }
    std::vector<double> out;
    for (int l = lo[0]; l < hi[0]; ++l)
        for (int m = lo[1]; m < hi[1]; ++m)
            for (int n = lo[2]; n < hi[2]; ++n) {
                const std::array<int, 3> k{l, m, n};
                double value = 0.0;
                int components = 0, nonZero = 0;
                for (int a = 0; a < g.dim; ++a) {
                    value += axisEigenvalue(g, a, k[a]);
                    components += g.isPeriodic(a) || k[a] >= 1;
                    nonZero += k[a] != 0;
                }
                int multiplicity = 1;
                if (field == Field::Velocity) multiplicity = components - (nonZero > 0);
                if (field == Field::Neumann && nonZero == 0) multiplicity = 0;
                for (int i = 0; i < multiplicity; ++i) out.push_back(value);
            }
    std::sort(out.begin(), out.end());
    return out;
}

/// Relative error to 1e-9; a zero (a harmonic field, the Dirichlet constant on a torus) against
/// the spectrum's largest value.
void expectSpectrum(const Eigen::VectorXd& computed, const std::vector<double>& exact,
                    const char* what) {
    ASSERT_LE(size_t(computed.size()), exact.size());
    const double scale = exact[size_t(computed.size()) - 1];
    double worst = 0.0;
    Eigen::Index at = 0;
    for (Eigen::Index i = 0; i < computed.size(); ++i) {
        const double reference = exact[size_t(i)];
        const double e = std::abs(computed[i] - reference) / (reference == 0.0 ? scale : reference);
        if (e > worst) worst = e, at = i;
    }
    EXPECT_LE(worst, 1e-9) << what << ": worst relative error " << worst << " at eigenvalue "
                           << at + 1 << " (computed " << computed[at] << ", exact "
                           << exact[size_t(at)] << ")";
}

SceneSpec periodicScene(std::array<int, 3> res, Vec3 lo, Vec3 hi, int dim,
                        std::array<bool, 3> periodic) {
    SceneSpec scene = testing::gridScene(res, lo, hi, dim);
    scene.grid.periodic = periodic;
    return scene;
}

int periodicAxes(const GridSpec& g) {
    return g.isPeriodic(0) + g.isPeriodic(1) + g.isPeriodic(2);
}

void checkPeriodicBox(SceneSpec scene, int velocityModes, int scalarModes) {
    scene.basis.velocityModes = {{1, velocityModes}};
    scene.basis.scalarModes = scalarModes;
    Progress quiet = Progress::silent();
    const BasisCache neumann = computeBasis(scene, quiet);
    expectSpectrum(neumann.velocity.eigenvalues, boxSpectrum(scene.grid, Field::Velocity),
                   "velocity");
    expectSpectrum(neumann.scalar.eigenvalues, boxSpectrum(scene.grid, Field::Neumann), "Neumann");
    EXPECT_EQ(neumann.velocity.harmonic, periodicAxes(scene.grid))
        << "one uniform flow per periodic axis";
    EXPECT_EQ(neumann.scalar.omittedConstants, 1);
    const BasisChecks checks = checkBasis(neumann);
    EXPECT_LE(checks.maxDivergence, 1e-10);
    EXPECT_LE(checks.velocityOrthonormality, 1e-10);
    EXPECT_LE(checks.scalarOrthonormality, 1e-10);

    scene.basis.scalarBoundary = ScalarBoundary::Dirichlet;
    const BasisCache dirichlet = computeBasis(scene, quiet);
    expectSpectrum(dirichlet.scalar.eigenvalues, boxSpectrum(scene.grid, Field::Dirichlet),
                   "Dirichlet");
}

TEST(PeriodicSpectrum, Torus2DMatchesDiscreteValuesExactly) {
    // Non-square cells and box.
    checkPeriodicBox(
        periodicScene({24, 20, 1}, {-1.0, 0.0, 0.0}, {1.25, 1.5, 0.0}, 2, {true, true, false}), 60,
        40);
}

TEST(PeriodicSpectrum, Channel2DMatchesDiscreteValuesExactly) {
    checkPeriodicBox(
        periodicScene({30, 16, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2, {true, false, false}), 60,
        40);
}

TEST(PeriodicSpectrum, Torus3DMatchesDiscreteValuesExactly) {
    checkPeriodicBox(
        periodicScene({10, 8, 12}, {0.0, 0.0, 0.0}, {1.2, 0.9, 1.0}, 3, {true, true, true}), 60,
        30);
}

TEST(PeriodicSpectrum, Slab3DPeriodicInXAndZMatchesDiscreteValuesExactly) {
    checkPeriodicBox(
        periodicScene({10, 8, 12}, {0.0, 0.0, 0.0}, {1.2, 0.9, 1.0}, 3, {true, false, true}), 60,
        30);
}

/// Harmonic count of a domain (the leading velocity modes with κ = 0), with the basis checked.
int harmonicCount(SceneSpec scene) {
    scene.basis.velocityModes = {{1, 8}};
    scene.basis.scalarModes = 2;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    testing::expectValidVelocityBasis(cache);
    return cache.velocity.harmonic;
}

TEST(PeriodicHarmonics, OnePerPeriodicAxisAndOnePerHole) {
    EXPECT_EQ(harmonicCount(periodicScene({16, 16, 1}, {0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, 2,
                                          {true, true, false})),
              2)
        << "2D torus";
    EXPECT_EQ(harmonicCount(periodicScene({8, 8, 8}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 3,
                                          {true, true, true})),
              3)
        << "3D torus";
    EXPECT_EQ(harmonicCount(periodicScene({16, 8, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2,
                                          {true, false, false})),
              1)
        << "2D channel";
    EXPECT_EQ(harmonicCount(testing::periodicChannelScene(32)), 2)
        << "2D channel around a disk: the flow along it and the circulation";
    SceneSpec torusWithDisk =
        periodicScene({32, 32, 1}, {0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, 2, {true, true, false});
    torusWithDisk.domain = {testing::box({-1.0, -1.0, 0.0}, {2.0, 2.0, 0.0}),
                            testing::ball({0.5, 0.5, 0.0}, 0.2, CsgOp::Subtract)};
    // On a torus the circulation around a hole is not free: the fundamental domain's edges cancel,
    // so it equals minus the (zero) curl outside the hole. A torus with a hole is a wedge of two
    // circles: two harmonic fields, the uniform flows.
    EXPECT_EQ(harmonicCount(torusWithDisk), 2) << "2D torus around a disk";
    EXPECT_EQ(harmonicCount(testing::periodicChannelScene(32, {false, false, false})), 1)
        << "the same disk between walls: its circulation";
}

TEST(PeriodicSeams, RefusesADomainThatDiffersAtTheTwoEnds) {
    // A disk cut by the seam at x = 0 only: it has no twin at x = 2.
    SceneSpec scene = testing::periodicChannelScene(32);
    scene.domain[1] = testing::ball({0.0, 0.5, 0.0}, 0.2, CsgOp::Subtract);
    Progress quiet = Progress::silent();
    try {
        computeBasis(scene, quiet);
        FAIL() << "a domain that differs across the seam was accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("[[domain]]: the domain does not repeat across periodic axis x"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("x = 0 and x = 2"), std::string::npos) << message;
    }
    // With its twin at the other end the domain repeats.
    scene.domain.push_back(testing::ball({2.0, 0.5, 0.0}, 0.2, CsgOp::Subtract));
    EXPECT_EQ(harmonicCount(scene), 2) << "a channel around one disk that straddles the seam";
}

TEST(PeriodicSeams, RefusesAWallOnTheSeam) {
    // A box domain that ends where the grid does: its walls would close the periodic axis.
    SceneSpec scene =
        periodicScene({16, 8, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2, {true, false, false});
    scene.domain = {testing::box({0.0, 0.2, 0.0}, {2.0, 0.8, 0.0})};
    Progress quiet = Progress::silent();
    try {
        computeBasis(scene, quiet);
        FAIL() << "a wall on the seam was accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(
            message.find("[[domain]]: a wall of the domain lies on the seam of periodic axis x"),
            std::string::npos)
            << message;
    }
}

}  // namespace
}  // namespace modeflow
