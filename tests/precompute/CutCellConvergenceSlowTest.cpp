// Curved and unaligned walls: eigenvalues converge to the continuum at second order with cut
// cells, first order with the staircase switch (tests/README.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "precompute/Precompute.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

// Bessel J_m zeros j_{m,n} and J'_m zeros j'_{m,n}, with multiplicity (2 for m > 0).
const std::vector<double> kDiskDirichlet = {2.404826, 3.831706, 3.831706, 5.135622, 5.135622,
                                            5.520078, 6.380162, 6.380162, 7.015587, 7.015587};
const std::vector<double> kDiskNeumann = {1.841184, 1.841184, 3.054237, 3.054237, 3.831706,
                                          4.201189, 4.201189, 5.317553, 5.317553, 5.331443};

double maxRelativeError(const Eigen::VectorXd& computed, const std::vector<double>& roots) {
    double worst = 0.0;
    for (size_t i = 0; i < roots.size(); ++i) {
        const double exact = roots[i] * roots[i];
        worst = std::max(worst, std::abs(computed[Eigen::Index(i)] - exact) / exact);
    }
    return worst;
}

struct DiskErrors {
    double velocity, neumann, dirichlet;
};

DiskErrors diskErrors(int n, BoundaryTreatment treatment) {
    SceneSpec scene = testing::unitBallScene(2, n);
    scene.basis.boundary = treatment;
    Progress quiet = Progress::silent();
    const BasisCache neumann = computeBasis(scene, quiet);
    SCOPED_TRACE(n);
    testing::expectValidVelocityBasis(neumann);
    scene.basis.scalarBoundary = ScalarBoundary::Dirichlet;
    scene.basis.velocityModes = {{1, 1}};
    const BasisCache dirichlet = computeBasis(scene, quiet);
    return {maxRelativeError(neumann.velocity.eigenvalues, kDiskDirichlet),
            maxRelativeError(neumann.scalar.eigenvalues, kDiskNeumann),
            maxRelativeError(dirichlet.scalar.eigenvalues, kDiskDirichlet)};
}

struct Orders {
    double velocity, neumann, dirichlet;
};

Orders observedOrders(BoundaryTreatment treatment, const char* label) {
    const DiskErrors coarse = diskErrors(64, treatment);
    const DiskErrors fine = diskErrors(256, treatment);
    auto order = [](double c, double f) { return std::log2(c / f) / 2.0; };
    const Orders o{order(coarse.velocity, fine.velocity), order(coarse.neumann, fine.neumann),
                   order(coarse.dirichlet, fine.dirichlet)};
    std::printf(
        "unit disk, %s, max relative error of the first 10 eigenvalues, 64² → 256²:\n"
        "  velocity  %.3e → %.3e  order %.2f\n"
        "  Neumann   %.3e → %.3e  order %.2f\n"
        "  Dirichlet %.3e → %.3e  order %.2f\n",
        label, coarse.velocity, fine.velocity, o.velocity, coarse.neumann, fine.neumann, o.neumann,
        coarse.dirichlet, fine.dirichlet, o.dirichlet);
    return o;
}

TEST(CutCellConvergence, DiskEigenvaluesConvergeQuadraticallyWithCutCells) {
    const Orders o = observedOrders(BoundaryTreatment::CutCell, "cut cells");
    EXPECT_GE(o.velocity, 1.8);
    EXPECT_GE(o.neumann, 1.8);
    EXPECT_GE(o.dirichlet, 1.8);
}

TEST(CutCellConvergence, DiskEigenvaluesConvergeLinearlyWithStaircase) {
    const Orders o = observedOrders(BoundaryTreatment::Staircase, "staircase");
    EXPECT_GE(o.velocity, 0.6);
    EXPECT_LE(o.velocity, 1.5);
    EXPECT_GE(o.neumann, 0.6);
    EXPECT_LE(o.neumann, 1.5);
    EXPECT_GE(o.dirichlet, 0.6);
    EXPECT_LE(o.dirichlet, 1.5);
}

}  // namespace
}  // namespace modeflow
