// Closed-form bases of whole boxes and tori (precompute/closedform) against the eigensolver on
// the same grid (walls, tori and mixed axes), and against dense periodic MAC operators built in
// the test (the whole div-free space): eigenvalues, multiplicities, spans.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "engine/core/Error.h"
#include "engine/format/SeparableModes.h"
#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/WholeBoxDofs.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"
#include "tests/support/WholeBoxReference.h"

namespace modeflow {
namespace {

/// The largest count ≤ n that ends a degenerate cluster of `values` (ascending).
Eigen::Index clusterEnd(const Eigen::VectorXd& values, Eigen::Index n) {
    while (n > 1 && std::abs(values[n] - values[n - 1]) <= 1e-8 * values[n]) --n;
    return n;
}

/// max |a − b| / |b|, where a zero eigenvalue (a torus's constant, which the eigensolver finds to
/// round-off) counts against a millionth of the largest instead.
double worstRelative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    const double floor = 1e-6 * b.cwiseAbs().maxCoeff();
    double worst = 0.0;
    for (Eigen::Index i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]) / std::max({std::abs(b[i]), floor, 1e-300}));
    return worst;
}

/// max |σ − 1| over the singular values of Qᵀ M P: 0 when the ⋆-orthonormal columns of P and Q
/// span the same space.
double spanDistance(const Eigen::MatrixXd& p, const Eigen::MatrixXd& q,
                    const Eigen::VectorXd& mass) {
    const Eigen::MatrixXd overlap = q.transpose() * mass.asDiagonal() * p;
    const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(overlap).singularValues();
    return (s.array() - 1.0).abs().maxCoeff();
}

Eigen::MatrixXd scalarColumns(const BasisCache& c) {
    return scalarModeValues(c.grid, c.scalar.cells, c.scalar.separable);
}

/// Both bases of `scene` in closed form and by the eigensolver: equal eigenvalues (1e-10
/// relative; Dirichlet 1e-9: the eigensolver's ghost-fluid wall sits 1e-10 h inside the box) and
/// equal spans of every whole degenerate cluster.
void expectEqualToEigensolver(SceneSpec scene, int velocityModes, int scalarModes,
                              std::vector<ScalarBoundary> boundaries = {
                                  ScalarBoundary::Neumann, ScalarBoundary::Dirichlet}) {
    scene.basis.velocityModes = {{1, velocityModes + 1}};
    scene.basis.scalarModes = scalarModes + 1;
    Progress quiet = Progress::silent();
    for (ScalarBoundary boundary : boundaries) {
        SCOPED_TRACE(std::string(boundary == ScalarBoundary::Dirichlet ? "Dirichlet" : "Neumann") +
                     ", periodic " + std::to_string(scene.grid.periodic[0]) +
                     std::to_string(scene.grid.periodic[1]) +
                     std::to_string(scene.grid.periodic[2]));
        scene.basis.scalarBoundary = boundary;
        BasisCache closed = computeBasis(scene, quiet);
        const BasisCache solved = computeBasis(scene, quiet, BasisMethod::Eigensolve);
        ASSERT_EQ(closed.velocity.source, BasisSource::ClosedForm);
        ASSERT_EQ(closed.scalar.source, BasisSource::ClosedForm);
        ASSERT_EQ(solved.velocity.source, BasisSource::Eigensolve);
        EXPECT_EQ(closed.faces, solved.faces);
        EXPECT_LE((closed.faceStar - solved.faceStar).cwiseAbs().maxCoeff(),
                  1e-14 * solved.faceStar.maxCoeff());
        EXPECT_EQ(closed.cells, solved.cells);

        const Eigen::Index nv = clusterEnd(closed.velocity.eigenvalues, velocityModes);
        EXPECT_LE(worstRelative(closed.velocity.eigenvalues.head(nv),
                                solved.velocity.eigenvalues.head(nv)),
                  1e-10);
        const Eigen::MatrixXd columns =
            velocityModeFluxes(closed.grid, closed.faces, closed.velocity.separable);
        EXPECT_LE(
            spanDistance(columns.leftCols(nv), solved.velocity.modes.leftCols(nv), solved.faceStar),
            1e-8);
        testing::expectValidVelocityBasis(closed);

        const bool dirichlet = boundary == ScalarBoundary::Dirichlet;
        const Eigen::Index ns = clusterEnd(closed.scalar.eigenvalues, scalarModes);
        EXPECT_LE(
            worstRelative(closed.scalar.eigenvalues.head(ns), solved.scalar.eigenvalues.head(ns)),
            dirichlet ? 1e-9 : 1e-10)
            << (dirichlet ? "Dirichlet" : "Neumann");
        EXPECT_EQ(closed.scalar.cells, solved.scalar.cells);
        EXPECT_LE(spanDistance(scalarColumns(closed).leftCols(ns), solved.scalar.modes.leftCols(ns),
                               solved.scalar.cellStar),
                  1e-8)
            << (dirichlet ? "Dirichlet" : "Neumann");
        EXPECT_EQ(closed.scalar.omittedConstants, solved.scalar.omittedConstants);
    }
}

TEST(ClosedFormBasis, EqualsTheEigensolverOnA2DBox) {
    // Non-square cells and box.
    expectEqualToEigensolver(testing::gridScene({14, 11, 1}, {-1.0, 0.0, 0.0}, {1.25, 1.5, 0.0}, 2),
                             60, 40);
}

TEST(ClosedFormBasis, EqualsTheEigensolverOnA3DBox) {
    // Every 3D wave vector with three non-zero wave numbers carries two fields: kept both.
    expectEqualToEigensolver(testing::gridScene({7, 6, 5}, {0.0, 0.0, 0.0}, {1.2, 0.9, 1.0}, 3), 80,
                             40);
}

/// `scene` with the given axes periodic.
SceneSpec withPeriodic(SceneSpec scene, std::array<bool, 3> periodic) {
    scene.grid.periodic = periodic;
    return scene;
}

TEST(ClosedFormBasis, EqualsTheEigensolverOnA2DTorusAndChannel) {
    const SceneSpec scene = testing::gridScene({10, 8, 1}, {0.0, 0.0, 0.0}, {1.25, 0.8, 0.0}, 2);
    expectEqualToEigensolver(withPeriodic(scene, {true, true, false}), 40, 30);
    expectEqualToEigensolver(withPeriodic(scene, {true, false, false}), 40, 30);
}

TEST(ClosedFormBasis, EqualsTheEigensolverOnA3DTorusAndMixedAxes) {
    const SceneSpec scene = testing::gridScene({6, 5, 4}, {0.0, 0.0, 0.0}, {1.2, 0.9, 1.0}, 3);
    expectEqualToEigensolver(withPeriodic(scene, {true, true, true}), 50, 30);
    expectEqualToEigensolver(withPeriodic(scene, {false, true, false}), 50, 30);
}

TEST(ClosedFormBasis, BoundaryTreatmentsAgreeOnAWholeBoxAndNoSlipIsSolved) {
    SceneSpec scene = testing::gridScene({6, 5, 4}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 3);
    Progress quiet = Progress::silent();
    const BasisCache cut = computeBasis(scene, quiet);
    scene.basis.boundary = BoundaryTreatment::Staircase;
    const BasisCache staircase = computeBasis(scene, quiet);
    EXPECT_EQ(staircase.velocity.separable, cut.velocity.separable);
    EXPECT_EQ(staircase.coefficients.value, cut.coefficients.value);
    scene.basis.wall = WallKind::NoSlip;
    EXPECT_EQ(computeBasis(scene, quiet).velocity.source, BasisSource::Eigensolve);
    scene.basis.wall = WallKind::FreeSlip;
    scene.domain = {testing::box({0.0, 0.0, 0.0}, {0.5, 1.0, 1.0})};
    EXPECT_EQ(computeBasis(scene, quiet).velocity.source, BasisSource::Eigensolve);
}

TEST(ClosedFormBasis, ModeRangesPickPositionsOfTheWholeSpectrum) {
    const GridSpec grid = testing::gridScene({6, 5, 4}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 3).grid;
    const ClosedFormVelocity all = closedFormVelocityBasis(grid, {{1, 30}});
    const ClosedFormVelocity shaped = closedFormVelocityBasis(grid, {{3, 7}, {21, 30}});
    ASSERT_EQ(shaped.modes.size(), 15u);
    for (std::size_t m = 0; m < shaped.modes.size(); ++m) {
        const int number = m < 5 ? int(m) + 3 : int(m) + 16;
        EXPECT_EQ(shaped.modeNumbers[m], number);
        EXPECT_EQ(shaped.modes[m], all.modes[std::size_t(number - 1)]);
        EXPECT_EQ(shaped.eigenvalues[Eigen::Index(m)], all.eigenvalues[number - 1]);
    }
    for (Eigen::Index m = 1; m < all.eigenvalues.size(); ++m)
        EXPECT_LE(all.eigenvalues[m - 1], all.eigenvalues[m]);
    try {
        closedFormVelocityBasis(grid, {{1, 1000}});
        ADD_FAILURE() << "asked for more modes than the grid holds";
    } catch (const Error& e) {
        // faces 5·5·4 + 6·4·4 + 6·5·3 − cells 6·5·4 + one component
        EXPECT_NE(std::string(e.what()).find("holds only 167 divergence-free fields"),
                  std::string::npos)
            << e.what();
    }
}

/// A whole box with periodic axes: the closed-form modes are eigenvectors of the dense periodic
/// L2 (residual), divergence-free, ⋆-orthonormal, as many as the div-free space holds, and their
/// κ² are that space's spectrum; likewise for the Neumann and Dirichlet scalars.
void expectPeriodicEigenbasis(GridSpec grid, int expectedHarmonic) {
    BasisCache cache;
    cache.grid = grid;
    fillWholeBoxDofs(cache);
    const testing::WholeBoxReference reference(cache);
    const Eigen::MatrixXd& d = reference.divergence();
    const Eigen::MatrixXd& l2 = reference.velocityLaplacian();
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(d);
    const Eigen::Index dimension = d.cols() - lu.rank();
    ASSERT_EQ(closedFormDivergenceFreeDimension(grid), dimension);

    const ClosedFormVelocity basis = closedFormVelocityBasis(grid, {{1, int(dimension)}});
    EXPECT_EQ(basis.harmonicCount, expectedHarmonic);
    const Eigen::MatrixXd modes = velocityModeFluxes(grid, cache.faces, basis.modes);
    const Eigen::VectorXd& star = cache.faceStar;
    const Eigen::MatrixXd residual =
        l2 * modes - star.asDiagonal() * modes * basis.eigenvalues.asDiagonal();
    EXPECT_LE(residual.cwiseAbs().maxCoeff(), 1e-12 * (l2 * modes).cwiseAbs().maxCoeff());
    EXPECT_LE((d * modes).cwiseAbs().maxCoeff(), 1e-12 * modes.cwiseAbs().maxCoeff());
    const Eigen::MatrixXd gram = modes.transpose() * star.asDiagonal() * modes;
    EXPECT_LE((gram - Eigen::MatrixXd::Identity(dimension, dimension)).cwiseAbs().maxCoeff(),
              1e-12);

    // The div-free spectrum of the dense operator: L2 on an orthonormal basis of ker d.
    const Eigen::VectorXd root = star.cwiseSqrt();
    const Eigen::MatrixXd kernel = lu.kernel();
    const Eigen::MatrixXd q =
        Eigen::HouseholderQR<Eigen::MatrixXd>(root.asDiagonal() * kernel).householderQ() *
        Eigen::MatrixXd::Identity(d.cols(), dimension);
    const Eigen::MatrixXd reduced = q.transpose() * root.cwiseInverse().asDiagonal() * l2 *
                                    root.cwiseInverse().asDiagonal() * q;
    Eigen::VectorXd spectrum =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(reduced).eigenvalues();
    const double top = spectrum.maxCoeff();
    for (Eigen::Index i = 0; i < dimension; ++i)
        EXPECT_NEAR(spectrum[i], basis.eigenvalues[i], 1e-11 * top) << "mode " << i + 1;

    for (ScalarBoundary boundary : {ScalarBoundary::Neumann, ScalarBoundary::Dirichlet}) {
        const bool dirichlet = boundary == ScalarBoundary::Dirichlet;
        Eigen::MatrixXd l3 = reference.neumannLaplacian();
        // Ghost-fluid Dirichlet walls: the wall faces' dual edges are half edges, weight 2|face|/h.
        if (dirichlet)
            for (int a = 0; a < grid.dim; ++a) {
                if (grid.isPeriodic(a)) continue;
                const MacGrid mac = MacGrid::fromSpec(grid);
                const double weight =
                    2.0 * mac.faceArea(a) / grid.spacing(a) / std::pow(mac.cellVolume(), 2);
                for (Eigen::Index c = 0; c < mac.cellCount(); ++c) {
                    std::array<int, 3> pos{int(c % mac.cells[0]),
                                           int(c / mac.cells[0] % mac.cells[1]),
                                           int(c / mac.cells[0] / mac.cells[1])};
                    l3(c, c) += weight * ((pos[a] == 0) + (pos[a] == grid.resolution[a] - 1));
                }
            }
        const Eigen::Index cells = l3.rows();
        const ClosedFormScalar scalar =
            closedFormScalarBasis(grid, int(cells) - (dirichlet ? 0 : 1), boundary);
        const Eigen::MatrixXd phi = scalarModeValues(grid, cache.cells, scalar.modes);
        const Eigen::MatrixXd r =
            l3 * phi - cache.cellStar.asDiagonal() * phi * scalar.eigenvalues.asDiagonal();
        EXPECT_LE(r.cwiseAbs().maxCoeff(), 1e-12 * (l3 * phi).cwiseAbs().maxCoeff())
            << (dirichlet ? "Dirichlet" : "Neumann");
        const Eigen::MatrixXd g = phi.transpose() * cache.cellStar.asDiagonal() * phi;
        EXPECT_LE((g - Eigen::MatrixXd::Identity(g.rows(), g.cols())).cwiseAbs().maxCoeff(), 1e-12);
    }
}

TEST(ClosedFormBasis, TorusAndChannelModesAreThePeriodicEigenbasis2D) {
    GridSpec grid = testing::gridScene({6, 5, 1}, {0.0, 0.0, 0.0}, {1.0, 0.8, 0.0}, 2).grid;
    grid.periodic = {true, true, false};
    expectPeriodicEigenbasis(grid, 2);  // a uniform flow along each periodic axis
    grid.periodic = {true, false, false};
    expectPeriodicEigenbasis(grid, 1);
    grid.resolution = {5, 4, 1};  // odd n: no l = n/2
    grid.periodic = {false, true, false};
    expectPeriodicEigenbasis(grid, 1);
}

TEST(ClosedFormBasis, TorusAndMixedAxesModesAreThePeriodicEigenbasis3D) {
    GridSpec grid = testing::gridScene({4, 3, 4}, {0.0, 0.0, 0.0}, {1.0, 0.8, 0.7}, 3).grid;
    grid.periodic = {true, true, true};
    expectPeriodicEigenbasis(grid, 3);
    grid.periodic = {true, false, true};
    expectPeriodicEigenbasis(grid, 2);
    grid.resolution = {3, 4, 2};
    grid.periodic = {false, true, false};
    expectPeriodicEigenbasis(grid, 1);
}

}  // namespace
}  // namespace modeflow
