// Whole-box domains must reproduce the plain MAC operators exactly (precompute/README.md;
// tests/README.md): every κ² and μ² equals a sum of 4/h² sin²(πl/2n) per axis, with the right
// multiplicity.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

double macEigenvalue(const GridSpec& g, int axis, int l) {
    const double s = std::sin(M_PI * l / (2.0 * g.resolution[axis]));
    return 4.0 / (g.spacing(axis) * g.spacing(axis)) * s * s;
}

enum class Field { Velocity, Neumann, Dirichlet };

/// Sorted discrete spectrum of a box. Velocity: wavevector (l,m[,n]) in [0,N) per axis carries
/// (number of non-zero indices − 1) div-free fields. Neumann: l ∈ [0,N), minus the constant.
/// Dirichlet (ghost value −u at the wall): l ∈ [1,N].
std::vector<double> boxSpectrum(const GridSpec& g, Field field) {
    std::vector<double> out;
    const int lo = field == Field::Dirichlet ? 1 : 0;
    const int hiShift = field == Field::Dirichlet ? 1 : 0;
    const int nz = g.dim == 3 ? g.resolution[2] + hiShift : lo + 1;
    for (int l = lo; l < g.resolution[0] + hiShift; ++l)
        for (int m = lo; m < g.resolution[1] + hiShift; ++m)
            for (int n = lo; n < nz; ++n) {
                const int nonzero = (l > 0) + (m > 0) + (n > 0);
                const double value = macEigenvalue(g, 0, l) + macEigenvalue(g, 1, m) +
                                     (g.dim == 3 ? macEigenvalue(g, 2, n) : 0.0);
                int multiplicity = 1;
                if (field == Field::Velocity) multiplicity = std::max(0, nonzero - 1);
                if (field == Field::Neumann && nonzero == 0) multiplicity = 0;
                for (int i = 0; i < multiplicity; ++i) out.push_back(value);
            }
    std::sort(out.begin(), out.end());
    return out;
}

void expectSpectrum(const Eigen::VectorXd& computed, const std::vector<double>& exact,
                    const char* what) {
    ASSERT_LE(size_t(computed.size()), exact.size());
    double worst = 0.0;
    Eigen::Index at = 0;
    for (Eigen::Index i = 0; i < computed.size(); ++i) {
        const double e = std::abs(computed[i] - exact[size_t(i)]) / exact[size_t(i)];
        if (e > worst) worst = e, at = i;
    }
    EXPECT_LE(worst, 1e-9) << what << ": worst relative error " << worst << " at eigenvalue "
                           << at + 1 << " (computed " << computed[at] << ", exact "
                           << exact[size_t(at)] << ")";
}

void checkBox(SceneSpec scene, int velocityModes, int scalarModes) {
    scene.basis.velocityModes = {{1, velocityModes}};
    scene.basis.scalarModes = scalarModes;
    Progress quiet = Progress::silent();
    scene.basis.scalarBoundary = ScalarBoundary::Neumann;
    const BasisCache neumann = computeBasis(scene, quiet);
    expectSpectrum(neumann.velocity.eigenvalues, boxSpectrum(scene.grid, Field::Velocity),
                   "velocity");
    expectSpectrum(neumann.scalar.eigenvalues, boxSpectrum(scene.grid, Field::Neumann), "Neumann");
    EXPECT_EQ(neumann.velocity.harmonic, 0);
    const BasisChecks checks = checkBasis(neumann);
    EXPECT_LE(checks.maxDivergence, 1e-10);
    EXPECT_LE(checks.velocityOrthonormality, 1e-10);
    EXPECT_LE(checks.scalarOrthonormality, 1e-10);

    scene.basis.scalarBoundary = ScalarBoundary::Dirichlet;
    const BasisCache dirichlet = computeBasis(scene, quiet);
    expectSpectrum(dirichlet.scalar.eigenvalues, boxSpectrum(scene.grid, Field::Dirichlet),
                   "Dirichlet");
}

TEST(BoxSpectrum, WholeGrid2DMatchesMacValuesExactly) {
    // Non-square cells (h_x != h_y) and a non-square box.
    checkBox(testing::gridScene({30, 24, 1}, {-1.0, 0.0, 0.0}, {1.25, 1.5, 0.0}, 2), 60, 40);
}

TEST(BoxSpectrum, WholeGrid3DMatchesMacValuesExactly) {
    checkBox(testing::gridScene({12, 10, 8}, {0.0, 0.0, 0.0}, {1.2, 0.9, 1.0}, 3), 60, 30);
}

TEST(BoxSpectrum, AlignedBoxDomainEqualsTheSmallerGrid) {
    // A box domain whose walls lie on grid planes must give the MAC values of the grid it spans:
    // no phantom elements from round-off on the wall.
    SceneSpec scene = testing::gridScene({32, 32, 1}, {-1.0, -1.0, 0.0}, {1.0, 1.0, 0.0}, 2);
    scene.domain = {testing::box({-0.5, -0.75, 0.0}, {0.75, 0.5, 0.0})};
    scene.basis.velocityModes = {{1, 30}};
    scene.basis.scalarModes = 20;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    const GridSpec spanned =
        testing::gridScene({20, 20, 1}, {-0.5, -0.75, 0.0}, {0.75, 0.5, 0.0}, 2).grid;
    expectSpectrum(cache.velocity.eigenvalues, boxSpectrum(spanned, Field::Velocity), "velocity");
    expectSpectrum(cache.scalar.eigenvalues, boxSpectrum(spanned, Field::Neumann), "Neumann");
    EXPECT_EQ(cache.cells.size(), 400u);
}

}  // namespace
}  // namespace modeflow
