/// @file TensorFreeDynamicsTest.cpp
/// The reduced dynamics on tensor-free coefficients (engine/dynamics/TensorFreeCoefficients.h)
/// follow the same trajectories as on the assembled tensor — every integrator, Euler, LANS-α with
/// viscosity, and MHD, 100 steps at N = 100 on a real cut-cell basis, within 1e-10 relative.
/// Jacobian–vector products (matrix-free Newton) are the assembled Jacobian's. The energy over
/// 1000 tensor-free steps: TensorFreeEnergySlowTest.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "engine/core/SceneKeywords.h"
#include "engine/dynamics/CachedCoefficients.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"

namespace modeflow {
namespace {

using testing::randomVector;

/// Both storages of the shared 100-mode basis.
struct Storages {
    const BasisCache& cache = testing::disk2dHundredModes();
    std::unique_ptr<StructuralCoefficients> dense =
        coefficientsFromCache(cache, CoefficientStorage::Dense);
    std::unique_ptr<StructuralCoefficients> free =
        coefficientsFromCache(cache, CoefficientStorage::TensorFree);
};

/// A step with h·|R(x)|/|Mx| = 0.05.
double stepFor(const ModalSystem& system, const Eigen::VectorXd& x) {
    Eigen::VectorXd r;
    system.rhs(x, r);
    return 0.05 * system.mass().cwiseProduct(x).norm() / r.norm();
}

/// Largest relative difference of the two systems' states over `steps` steps from x.
double trajectoryDifference(const ModalSystem& dense, const ModalSystem& free, Integrator scheme,
                            const Eigen::VectorXd& x, int steps) {
    ModalIntegrator a(dense, {scheme}), b(free, {scheme});
    const double h = stepFor(dense, x);
    Eigen::VectorXd xa = x, xb = x;
    double worst = 0.0;
    for (int s = 0; s < steps; ++s) {
        a.step(xa, h);
        b.step(xb, h);
        worst = std::max(worst, (xa - xb).norm() / xa.norm());
    }
    EXPECT_GT((xa - x).norm(), 0.1 * x.norm()) << "the state hardly moved: a weak test";
    return worst;
}

class TensorFreeTrajectory : public ::testing::TestWithParam<Integrator> {};

TEST_P(TensorFreeTrajectory, EulerFollowsTheTensor) {
    const Storages s;
    const FluidSystem dense(*s.dense), free(*s.free);
    const double d = trajectoryDifference(dense, free, GetParam(), randomVector(100, 31), 100);
    EXPECT_LT(d, 1e-10) << "largest relative state difference " << d;
}

TEST_P(TensorFreeTrajectory, LansAlphaWithViscosityFollowsTheTensor) {
    const Storages s;
    const FluidParameters parameters{s.cache.velocity.eigenvalues, 1e-3, 0.05};
    const FluidSystem dense(*s.dense, parameters), free(*s.free, parameters);
    const double d = trajectoryDifference(dense, free, GetParam(), randomVector(100, 32), 100);
    EXPECT_LT(d, 1e-10) << "largest relative state difference " << d;
}

TEST_P(TensorFreeTrajectory, MhdFollowsTheTensor) {
    if (GetParam() == Integrator::Linearized) GTEST_SKIP() << "the linearized rule is for fluids";
    const Storages s;
    const MhdParameters parameters{s.cache.velocity.eigenvalues, 1e-3, 2e-3, true};
    const MhdSystem dense(*s.dense, parameters), free(*s.free, parameters);
    const Eigen::VectorXd x = dense.state(randomVector(100, 33), 0.5 * randomVector(100, 34));
    const double d = trajectoryDifference(dense, free, GetParam(), x, 100);
    EXPECT_LT(d, 1e-10) << "largest relative state difference " << d;
}

INSTANTIATE_TEST_SUITE_P(Integrators, TensorFreeTrajectory,
                         ::testing::Values(Integrator::Explicit, Integrator::Rk4,
                                           Integrator::Midpoint, Integrator::Trapezoidal,
                                           Integrator::Linearized),
                         [](const auto& info) { return std::string(sceneKeyword(info.param)); });

/// |J_free·u − J_dense·u| / |J_dense·u| for the product without a Jacobian.
double productDifference(const ModalSystem& dense, const ModalSystem& free,
                         const Eigen::VectorXd& x) {
    const Eigen::VectorXd u = randomVector(x.size(), 41);
    Eigen::VectorXd r, want, got;
    Eigen::MatrixXd jac;
    dense.linearize(x, r, jac);
    want = jac * u;
    free.jacobianProduct(x, u, got);
    return (got - want).norm() / want.norm();
}

TEST(TensorFreeJacobian, ProductsAreTheAssembledJacobians) {
    const Storages s;
    const FluidParameters lans{s.cache.velocity.eigenvalues, 0.0, 0.05};
    const FluidSystem denseFluid(*s.dense, lans), freeFluid(*s.free, lans);
    const double fluid = productDifference(denseFluid, freeFluid, randomVector(100, 42));
    EXPECT_LT(fluid, 1e-12) << "LANS-α";
    const MhdSystem denseMhd(*s.dense), freeMhd(*s.free);
    const double mhd = productDifference(
        denseMhd, freeMhd, denseMhd.state(randomVector(100, 43), randomVector(100, 44)));
    EXPECT_LT(mhd, 1e-12) << "MHD";
}

}  // namespace
}  // namespace modeflow
