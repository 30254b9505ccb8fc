/// @file TensorFreeEnergySlowTest.cpp
/// The midpoint rule on tensor-free coefficients (engine/dynamics/TensorFreeCoefficients.h) keeps
/// the energy to 1e-9 over 1000 steps at N = 100 on a real cut-cell basis, solved without forming
/// a Jacobian (label slow: tests/README.md, "Reliability").

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Core>

#include "engine/dynamics/CachedCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"

namespace modeflow {
namespace {

TEST(TensorFreeMidpoint, KeepsTheEnergyOver1000Steps) {
    const std::unique_ptr<StructuralCoefficients> coefficients =
        coefficientsFromCache(testing::disk2dHundredModes(), CoefficientStorage::TensorFree);
    const FluidSystem system(*coefficients);
    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd v = testing::randomVector(100, 35);
    // Four times the step with h·|R(v)|/|Mv| = 0.05.
    Eigen::VectorXd r;
    system.rhs(v, r);
    const double h = 4.0 * 0.05 * system.mass().cwiseProduct(v).norm() / r.norm(), e0 = energy(v);
    double drift = 0.0;
    for (int step = 0; step < 1000; ++step) {
        const StepReport report = midpoint.step(v, h);
        ASSERT_NE(report.solver, NewtonSolver::DenseLu)
            << "a tensor-free Jacobian costs O(E·N²): no LU";
        drift = std::max(drift, std::abs(energy(v) - e0) / e0);
    }
    EXPECT_LE(drift, 1e-9) << "largest relative energy change " << drift;
}

}  // namespace
}  // namespace modeflow
