// The sparse structural coefficients of closed-form bases (selection rules) against the
// quadrature on their materialized modes: the production assembly on wall boxes, the same
// quadrature with wrapped face look-ups on periodic axes (tests/support/WholeBoxReference.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "engine/core/PackedLayout.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/ClosedFormCoefficients.h"
#include "precompute/closedform/WholeBoxDofs.h"
#include "precompute/coefficients/CoefficientAssembly.h"
#include "precompute/geometry/Domain.h"
#include "tests/support/TestScenes.h"
#include "tests/support/WholeBoxReference.h"

namespace modeflow {
namespace {

/// The sparse entries as a packed k < j array, every (k, i, j) at most once.
std::vector<double> packed(const BasisCache::Coefficients& c, int n) {
    std::vector<double> out(packedSize(std::size_t(n)), 0.0);
    std::set<std::tuple<int, int, int>> seen;
    for (std::size_t e = 0; e < c.value.size(); ++e) {
        EXPECT_LT(c.k[e], c.j[e]);
        EXPECT_TRUE(seen.insert({c.k[e], c.i[e], c.j[e]}).second) << "entry given twice";
        out[packedIndex(std::size_t(n), std::size_t(c.k[e]), std::size_t(c.i[e]),
                        std::size_t(c.j[e]))] = c.value[e];
    }
    return out;
}

/// max |a − b| / max |b|.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double diff = 0.0, size = 0.0;
    for (std::size_t x = 0; x < a.size(); ++x) {
        diff = std::max(diff, std::abs(a[x] - b[x]));
        size = std::max(size, std::abs(b[x]));
    }
    return diff / size;
}

/// Wall box: equal to assembleStructuralCoefficients on the materialized modes (the quadrature
/// the eigensolved bases get), to 1e-10 of max |C|.
void expectEqualToQuadrature(const GridSpec& grid, int modes) {
    BasisCache cache;
    cache.grid = grid;
    fillWholeBoxDofs(cache);
    const ClosedFormVelocity basis = closedFormVelocityBasis(grid, {{1, modes}});
    const Eigen::MatrixXd columns = velocityModeFluxes(grid, cache.faces, basis.modes);

    const CubicalComplex complex(grid);
    const Domain domain({}, grid.dim, grid.spacing(0));
    const CutCellMeasures measures =
        measureCutCells(complex, domain, BoundaryTreatment::CutCell, 1);
    const CutCellDec dec = buildCutCellDec(complex, measures, WallKind::FreeSlip);
    ASSERT_EQ(dec.faces.toGlobal, cache.faces);
    const std::vector<double> quadrature =
        assembleStructuralCoefficients(complex, measures, dec, columns);
    const BasisCache::Coefficients sparse = assembleClosedFormCoefficients(grid, basis.modes);
    // The test's wrapped quadrature (used on periodic axes below) is the production one here.
    const std::vector<double> full = testing::WholeBoxReference(cache).coefficients(columns);
    double mismatch = 0.0;
    for (int k = 0; k < modes; ++k)
        for (int i = 0; i < modes; ++i)
            for (int j = k + 1; j < modes; ++j)
                mismatch = std::max(
                    mismatch, std::abs(full[std::size_t((k * modes + i) * modes + j)] -
                                       quadrature[packedIndex(std::size_t(modes), std::size_t(k),
                                                              std::size_t(i), std::size_t(j))]));
    EXPECT_LE(mismatch, 1e-12 * *std::max_element(full.begin(), full.end()));
    const double error = relativeDifference(packed(sparse, modes), quadrature);
    EXPECT_LE(error, 1e-10);
    std::size_t nonZero = 0;
    double largest = 0.0;
    for (double x : quadrature) largest = std::max(largest, std::abs(x));
    for (double x : quadrature) nonZero += std::abs(x) > 1e-12 * largest;
    EXPECT_EQ(sparse.value.size(), nonZero) << "the selection rules keep exactly the non-zeros";
    EXPECT_DOUBLE_EQ(sparse.density, double(nonZero) / double(quadrature.size()));
    std::printf("[ measured ] %dD box, %d modes: |C − quadrature| / max|C| = %.2e, %zu non-zeros\n",
                grid.dim, modes, error, nonZero);
}

TEST(ClosedFormCoefficients, EqualTheQuadratureOnA2DBox) {
    expectEqualToQuadrature(
        testing::gridScene({12, 9, 1}, {-1.0, 0.0, 0.0}, {1.25, 1.5, 0.0}, 2).grid, 60);
}

TEST(ClosedFormCoefficients, EqualTheQuadratureOnA3DBox) {
    expectEqualToQuadrature(testing::gridScene({7, 6, 5}, {0.0, 0.0, 0.0}, {1.2, 0.9, 1.0}, 3).grid,
                            70);
}

/// Periodic axes: equal to the wrapped quadrature on the materialized modes.
void expectEqualToWrappedQuadrature(GridSpec grid, std::array<bool, 3> periodic, int modes) {
    grid.periodic = periodic;
    BasisCache cache;
    cache.grid = grid;
    fillWholeBoxDofs(cache);
    const ClosedFormVelocity basis = closedFormVelocityBasis(grid, {{1, modes}});
    const Eigen::MatrixXd columns = velocityModeFluxes(grid, cache.faces, basis.modes);
    const std::vector<double> full = testing::WholeBoxReference(cache).coefficients(columns);
    std::vector<double> reference(packedSize(std::size_t(modes)));
    double antisymmetry = 0.0, largest = 0.0;
    for (int k = 0; k < modes; ++k)
        for (int i = 0; i < modes; ++i)
            for (int j = 0; j < modes; ++j) {
                const double c = full[std::size_t((k * modes + i) * modes + j)];
                largest = std::max(largest, std::abs(c));
                antisymmetry = std::max(
                    antisymmetry, std::abs(c + full[std::size_t((j * modes + i) * modes + k)]));
                if (k < j)
                    reference[packedIndex(std::size_t(modes), std::size_t(k), std::size_t(i),
                                          std::size_t(j))] = c;
            }
    EXPECT_LE(antisymmetry, 1e-13 * largest) << "the reference quadrature itself";
    const double error = relativeDifference(
        packed(assembleClosedFormCoefficients(grid, basis.modes), modes), reference);
    EXPECT_LE(error, 1e-10);
    std::printf(
        "[ measured ] %dD periodic [%d %d %d], %d modes: |C − quadrature| / max|C| = %.2e\n",
        grid.dim, periodic[0], periodic[1], periodic[2], modes, error);
}

TEST(ClosedFormCoefficients, EqualTheWrappedQuadratureOnPeriodicAxes2D) {
    const GridSpec grid = testing::gridScene({6, 5, 1}, {0.0, 0.0, 0.0}, {1.0, 0.8, 0.0}, 2).grid;
    expectEqualToWrappedQuadrature(grid, {true, true, false}, 31);  // all of them
    expectEqualToWrappedQuadrature(grid, {true, false, false}, 25);
    expectEqualToWrappedQuadrature(grid, {false, true, false}, 24);
}

TEST(ClosedFormCoefficients, EqualTheWrappedQuadratureOnPeriodicAxes3D) {
    const GridSpec grid = testing::gridScene({4, 3, 4}, {0.0, 0.0, 0.0}, {1.0, 0.8, 0.7}, 3).grid;
    expectEqualToWrappedQuadrature(grid, {true, true, true}, 45);
    expectEqualToWrappedQuadrature(grid, {true, false, true}, 45);
    expectEqualToWrappedQuadrature(grid, {false, true, false}, 40);
}

TEST(ClosedFormCoefficients, TheNonZeroEstimateBoundsTheCountFromAbove) {
    // The memory estimates use it: never below the count, and not far above.
    for (const int dim : {2, 3}) {
        const int n = dim == 3 ? 20 : 64, modes = 600;
        const GridSpec grid = testing::gridScene({n, n, dim == 3 ? n : 1}, {0.0, 0.0, 0.0},
                                                 {1.0, 1.0, dim == 3 ? 1.0 : 0.0}, dim)
                                  .grid;
        const ClosedFormVelocity basis = closedFormVelocityBasis(grid, {{1, modes}});
        const double count = double(assembleClosedFormCoefficients(grid, basis.modes).value.size());
        const double ratio = count / estimatedClosedFormNonZeros(dim, modes);
        EXPECT_LE(ratio, 1.0) << dim << "D: " << count << " non-zeros";
        EXPECT_GE(ratio, 0.7) << dim << "D: " << count << " non-zeros";
        std::printf("[ measured ] %dD, %d modes: %.0f non-zeros, %.2f of the estimate\n", dim,
                    modes, count, ratio);
    }
}

}  // namespace
}  // namespace modeflow
