// Whole-box domains must reproduce the plain MAC operators exactly (precompute/README.md;
// tests/README.md): every κ² and μ² equals a sum of 4/h² sin²(πl/2n) per axis, with the right
// multiplicity.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/core/MacGrid.h"
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

/// One axis of a box with open sides (GridSpec::open), as the cell-centred MAC operators see it:
/// a wall holds the normal flux at 0 (a Neumann pressure), an open side the pressure at 0 a half
/// cell out. Along it the pressure's profiles are cos θ(j+½) (a wall at the low side) or
/// sin θ(j+½) (open at both), the normal flux's the differences of it, sin θj or cos θj at the
/// faces j; θ = πl/n between walls, π(l+½)/n with one side open (a quarter wave), πl/n open at
/// both. A profile counts when it is not zero on its DOFs.
struct OpenAxis {
    int n = 1;
    int openSides = 0;  ///< 0, 1 (the high side) or 2
    int waves() const { return openSides == 2 ? n + 1 : n; }
    double theta(int l) const { return M_PI * (l + (openSides == 1 ? 0.5 : 0.0)) / n; }
    bool cellProfile(int l) const { return openSides == 2 ? l > 0 : true; }
    bool faceProfile(int l) const { return openSides == 0 ? l > 0 : true; }
};

/// The sorted spectra of a box with open sides: velocity (each wave vector carries its flux
/// components less the gradient of its pressure mode, when it has both) and pressure (every
/// pressure mode with a non-zero gradient: the non-constant "Neumann" ones).
std::pair<std::vector<double>, std::vector<double>> openBoxSpectra(const GridSpec& g) {
    std::vector<OpenAxis> axes;
    for (int a = 0; a < g.dim; ++a)
        axes.push_back({g.resolution[a], int(g.isOpen(a, false)) + int(g.isOpen(a, true))});
    std::vector<double> velocity, pressure;
    std::array<int, 3> l{0, 0, 0};
    const int nz = g.dim == 3 ? axes[2].waves() : 1;
    for (l[0] = 0; l[0] < axes[0].waves(); ++l[0])
        for (l[1] = 0; l[1] < axes[1].waves(); ++l[1])
            for (l[2] = 0; l[2] < nz; ++l[2]) {
                double value = 0.0;
                bool pressureMode = true;
                int components = 0;
                for (int a = 0; a < g.dim; ++a) {
                    const double s = std::sin(axes[a].theta(l[a]) / 2.0);
                    value += 4.0 / (g.spacing(a) * g.spacing(a)) * s * s;
                    pressureMode &= axes[a].cellProfile(l[a]);
                    bool component = axes[a].faceProfile(l[a]);
                    for (int b = 0; b < g.dim; ++b)
                        if (b != a) component &= axes[b].cellProfile(l[b]);
                    components += component;
                }
                const bool gradient = pressureMode && components > 0;
                for (int i = 0; i < components - int(gradient); ++i) velocity.push_back(value);
                if (gradient) pressure.push_back(value);
            }
    std::sort(velocity.begin(), velocity.end());
    std::sort(pressure.begin(), pressure.end());
    return {velocity, pressure};
}

/// A whole box with `open` sides: its bases are the quarter-wave MAC spectra, its fields
/// divergence-free with flux through the open sides, and a pair of opposite open sides whose
/// axis meets no other open side adds the flow straight through as a harmonic field.
void checkOpenBox(SceneSpec scene, std::array<bool, 6> open, int velocityModes, int harmonic) {
    scene.grid.open = open;
    scene.basis.velocityModes = {{1, velocityModes}};
    scene.basis.scalarModes = 20;
    scene.basis.scalarBoundary = ScalarBoundary::Neumann;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    EXPECT_EQ(cache.velocity.source, BasisSource::Eigensolve);  // no closed form with open sides
    const auto [velocity, pressure] = openBoxSpectra(scene.grid);
    for (Eigen::Index i = 0; i < harmonic; ++i) {
        EXPECT_EQ(velocity[size_t(i)], 0.0);
        EXPECT_LE(std::abs(cache.velocity.eigenvalues[i]), 1e-9);
    }
    expectSpectrum(cache.velocity.eigenvalues.tail(velocityModes - harmonic),
                   std::vector<double>(velocity.begin() + harmonic, velocity.end()), "velocity");
    expectSpectrum(cache.scalar.eigenvalues, pressure, "pressure");
    EXPECT_EQ(cache.velocity.harmonic, harmonic);
    EXPECT_EQ(cache.scalar.omittedConstants, 0);
    const BasisChecks checks = checkBasis(cache);
    EXPECT_LE(checks.maxDivergence, 1e-10);
    EXPECT_LE(checks.velocityOrthonormality, 1e-10);
    // The open sides' faces are degrees of freedom, and the modes carry flux through them.
    const MacGrid mac = MacGrid::fromSpec(scene.grid);
    std::vector<int> sideFace(size_t(mac.faceTotal()), 0);  // 1: on a side, 2: on a wall
    for (int axis = 0; axis < mac.dim; ++axis) {
        const std::array<int, 3> e = mac.faceExtent(axis);
        for (int z = 0; z < e[2]; ++z)
            for (int y = 0; y < e[1]; ++y)
                for (int x = 0; x < e[0]; ++x) {
                    const int along = std::array<int, 3>{x, y, z}[size_t(axis)];
                    if (along == 0 || along == mac.cells[axis])
                        sideFace[size_t(mac.faceIndex(axis, x, y, z))] =
                            mac.isWallFace(axis, along) ? 2 : 1;
                }
    }
    double openFlux = 0.0;
    for (size_t i = 0; i < cache.faces.size(); ++i) {
        const int side = sideFace[size_t(cache.faces[i])];
        EXPECT_NE(side, 2) << "a wall face is a degree of freedom: " << cache.faces[i];
        if (side == 1) openFlux += cache.velocity.modes.row(Eigen::Index(i)).cwiseAbs().sum();
    }
    EXPECT_GT(openFlux, 1.0);
}

TEST(BoxSpectrum, OpenTopBoxIsQuarterWaves2D) {
    checkOpenBox(testing::gridScene({10, 8, 1}, {0.0, 0.0, 0.0}, {1.25, 1.0, 0.0}, 2),
                 {false, false, false, true, false, false}, 40, 0);
}

TEST(BoxSpectrum, BoxOpenAtBothEndsHasTheFlowThroughAsItsHarmonicField2D) {
    checkOpenBox(testing::gridScene({8, 10, 1}, {0.0, 0.0, 0.0}, {0.8, 1.0, 0.0}, 2),
                 {false, false, true, true, false, false}, 40, 1);
}

TEST(BoxSpectrum, OpenSidesAcrossTwoAxes3D) {
    // Open at z_max and at both x sides: the flow straight along x is no harmonic field, as
    // the open top holds its tangential velocity at 0 (a quarter wave in z, κ² > 0).
    checkOpenBox(testing::gridScene({6, 5, 4}, {0.0, 0.0, 0.0}, {1.2, 1.0, 0.8}, 3),
                 {true, true, false, false, false, true}, 50, 0);
    // Open at both z sides alone: the flow straight up is.
    checkOpenBox(testing::gridScene({5, 4, 6}, {0.0, 0.0, 0.0}, {1.0, 0.8, 1.2}, 3),
                 {false, false, false, false, true, true}, 50, 1);
}

}  // namespace
}  // namespace modeflow
