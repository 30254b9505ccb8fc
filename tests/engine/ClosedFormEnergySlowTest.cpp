/// @file ClosedFormEnergySlowTest.cpp
/// The midpoint rule on the sparse closed-form coefficients of a 3D box at N = 2000 (matrix-free
/// implicit steps: no Jacobian is formed) conserves the energy to 1e-9 over 1000 steps. Slow: a
/// few minutes on the one thread a test gets in the suite (the time is printed).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "engine/dynamics/CachedCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/ClosedFormCoefficients.h"
#include "tests/support/RandomCoefficients.h"

namespace modeflow {
namespace {

TEST(ClosedFormEnergy, MidpointConservesEnergyAtTwoThousandModesIn3D) {
    constexpr int kModes = 2000, kSteps = 1000;
    BasisCache cache;
    cache.grid.dim = 3;
    cache.grid.resolution = {16, 16, 16};
    const ClosedFormVelocity basis = closedFormVelocityBasis(cache.grid, {{1, kModes}});
    cache.velocity.eigenvalues = basis.eigenvalues;
    cache.coefficients = assembleClosedFormCoefficients(cache.grid, basis.modes);
    const auto c = coefficientsFromCache(cache);
    const FluidSystem system(*c);
    IntegratorSettings settings{Integrator::Midpoint};
    ModalIntegrator midpoint(system, settings);

    Eigen::VectorXd v = testing::randomVector(kModes, 11), r;
    v *= std::sqrt(2.0) / v.norm();  // ½|v|² = 1
    c->apply(v, v, r);
    const double h = 0.05 * v.norm() / r.norm();  // 5% of a turnover per step
    const double e0 = energy(v);
    double drift = 0.0;
    long iterations = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < kSteps; ++s) {
        const StepReport report = midpoint.step(v, h);
        ASSERT_TRUE(report.converged) << "step " << s << ", residual " << report.residual;
        ASSERT_NE(report.solver, NewtonSolver::DenseLu);
        iterations += report.iterations;
        drift = std::max(drift, std::abs(energy(v) - e0) / e0);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LE(drift, 1e-9);
    std::printf(
        "[ measured ] N = %d, %zu non-zeros, %d midpoint steps: energy drift %.2e, "
        "%.1f iterations per step, %.1f s\n",
        kModes, cache.coefficients.value.size(), kSteps, drift, double(iterations) / kSteps,
        seconds);
}

}  // namespace
}  // namespace modeflow
