// A periodic channel around a disk (a cylinder in a periodic channel): its eigenvalues converge
// at second order with cut cells, like the walled domains of CutCellConvergenceSlowTest.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "precompute/Precompute.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// The first `count` non-zero κ² of the channel around a disk at nx cells along it.
Eigen::VectorXd channelEigenvalues(int nx, int count, BoundaryTreatment treatment) {
    SceneSpec scene = testing::periodicChannelScene(nx);
    scene.basis.boundary = treatment;
    scene.basis.velocityModes = {{1, count + 2}};
    scene.basis.scalarModes = 1;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    SCOPED_TRACE(nx);
    testing::expectValidVelocityBasis(cache);
    EXPECT_EQ(cache.velocity.harmonic, 2);
    return cache.velocity.eigenvalues.tail(count);
}

TEST(PeriodicConvergence, ChannelAroundADiskConvergesQuadraticallyWithCutCells) {
    // No closed form: the reference is the 512-cell grid (its own error, a sixteenth of the
    // 128-cell one's at second order, biases the orders up by about 0.1). The self-convergence
    // order log2(|κ²64 − κ²128| / |κ²128 − κ²256|) needs no reference at all.
    const int count = 10;
    const Eigen::VectorXd reference = channelEigenvalues(512, count, BoundaryTreatment::CutCell);
    const Eigen::VectorXd at64 = channelEigenvalues(64, count, BoundaryTreatment::CutCell);
    const Eigen::VectorXd at128 = channelEigenvalues(128, count, BoundaryTreatment::CutCell);
    const Eigen::VectorXd at256 = channelEigenvalues(256, count, BoundaryTreatment::CutCell);
    const auto error = [&](const Eigen::VectorXd& k2) {
        return ((k2 - reference).cwiseQuotient(reference)).cwiseAbs().maxCoeff();
    };
    const double e64 = error(at64), e128 = error(at128), e256 = error(at256);
    const double selfOrder =
        std::log2((at64 - at128).cwiseQuotient(reference).cwiseAbs().maxCoeff() /
                  (at128 - at256).cwiseQuotient(reference).cwiseAbs().maxCoeff());
    std::printf(
        "periodic channel around a disk, cut cells, max relative error of the first %d non-zero "
        "κ²\n"
        "against 512 cells along it: 64 %.3e, 128 %.3e (order %.2f), 256 %.3e (order %.2f); "
        "self-convergence 64/128/256: order %.2f\n",
        count, e64, e128, std::log2(e64 / e128), e256, std::log2(e128 / e256), selfOrder);
    EXPECT_GE(std::log2(e64 / e128), 1.8);
    EXPECT_GE(selfOrder, 1.8);
}

}  // namespace
}  // namespace modeflow
