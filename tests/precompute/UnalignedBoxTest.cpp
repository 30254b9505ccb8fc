// A box domain whose walls cut through cells: velocity κ² converge to the continuum free-slip
// values π²(l²/a² + m²/b² (+ n²/c²)).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "precompute/Precompute.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// Continuum free-slip div-free spectrum of a box: wavevector (l,m,n) ≥ 0 carries
/// (number of non-zero indices − 1) fields.
std::vector<double> continuumBoxSpectrum(const std::vector<double>& sides, int count) {
    std::vector<double> out;
    const int nz = sides.size() == 3 ? 12 : 1;
    for (int l = 0; l < 12; ++l)
        for (int m = 0; m < 12; ++m)
            for (int n = 0; n < nz; ++n) {
                const int nonzero = (l > 0) + (m > 0) + (n > 0);
                double k2 = std::pow(M_PI * l / sides[0], 2) + std::pow(M_PI * m / sides[1], 2);
                if (sides.size() == 3) k2 += std::pow(M_PI * n / sides[2], 2);
                for (int i = 1; i < nonzero; ++i) out.push_back(k2);
            }
    std::sort(out.begin(), out.end());
    out.resize(size_t(count));
    return out;
}

double boxError(int dim, int n, const Vec3& lo, const Vec3& hi, int count) {
    SceneSpec scene = testing::gridScene({n, n, n}, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, dim);
    scene.domain = {testing::box(lo, hi)};
    scene.basis.velocityModes = {{1, count}};
    scene.basis.scalarModes = 0;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    testing::expectValidVelocityBasis(cache);
    std::vector<double> sides;
    for (int a = 0; a < dim; ++a) sides.push_back(hi[a] - lo[a]);
    const std::vector<double> exact = continuumBoxSpectrum(sides, count);
    double worst = 0.0;
    for (int i = 0; i < count; ++i)
        worst = std::max(
            worst, std::abs(cache.velocity.eigenvalues[i] - exact[size_t(i)]) / exact[size_t(i)]);
    return worst;
}

void expectConvergence(int dim, int coarse, int fine, const Vec3& lo, const Vec3& hi, int count) {
    const double ec = boxError(dim, coarse, lo, hi, count);
    const double ef = boxError(dim, fine, lo, hi, count);
    const double order = std::log2(ec / ef) / std::log2(double(fine) / coarse);
    std::printf("%dD unaligned box, first %d κ²: error %.3e at %d, %.3e at %d, order %.2f\n", dim,
                count, ec, coarse, ef, fine, order);
    EXPECT_LT(ef, ec / 2.5);
    EXPECT_GE(order, 1.5);
}

TEST(UnalignedBox, VelocityEigenvaluesConverge2D) {
    expectConvergence(2, 32, 128, {-0.37, -0.29, 0.0}, {0.411, 0.337, 0.0}, 10);
}

TEST(UnalignedBox, VelocityEigenvaluesConverge3D) {
    expectConvergence(3, 12, 24, {-0.37, -0.29, -0.33}, {0.411, 0.337, 0.21}, 10);
}

}  // namespace
}  // namespace modeflow
