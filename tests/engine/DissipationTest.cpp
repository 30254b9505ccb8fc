/// @file DissipationTest.cpp
/// Viscosity by exact per-mode exponentials (seed §6.3.5), operator-split around every scheme,
/// with the arbitrary κ² order of frequency-shaped bases; held modes ([forcing]) that feed the
/// energy viscosity takes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/RandomCoefficients.h"

namespace modeflow {
namespace {

using testing::randomFullTensor;
using testing::randomVector;
using testing::shapedKappaSquared;

TEST(Viscosity, LoneModeDecaysExactlyForAnyStep) {
    const int n = 20, lone = 7;
    std::vector<double> full = randomFullTensor(n, 401);
    for (int k = 0; k < n; ++k) {  // no self-interaction: C[k][m][m] = 0, so R(e_m) = 0
        full[(k * n + lone) * n + lone] = 0.0;
        full[(lone * n + lone) * n + k] = 0.0;
    }
    const DenseCoefficients c = DenseCoefficients::fromFull(n, full);
    const double nu = 0.013;
    const Eigen::VectorXd k2 = shapedKappaSquared(n);
    const FluidSystem system(c, {k2, nu, 0.0});
    const double time = 10.0, amplitude = 1.7;
    for (Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                              Integrator::Trapezoidal, Integrator::Linearized}) {
        for (int steps : {1, 3, 100, 10000}) {
            ModalIntegrator integrator(system, {scheme});
            Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
            v[lone] = amplitude;
            for (int s = 0; s < steps; ++s) integrator.step(v, time / steps);
            const double expected = amplitude * std::exp(-nu * k2[lone] * time);
            // Exact up to the round-off of 2·steps multiplications by e^{−νκ²h/2}.
            EXPECT_NEAR(v[lone] / expected, 1.0, 1e-14 + 1e-16 * 2 * steps)
                << sceneKeyword(scheme) << ", " << steps << " steps";
            v[lone] = 0.0;
            EXPECT_EQ(v.norm(), 0.0) << "other modes were excited";
        }
    }
}

TEST(HeldModes, KeepTheirAmplitudeUnderEverySchemeAndFeedTheOthers) {
    const int n = 24;
    const DenseCoefficients c = DenseCoefficients::fromFull(n, randomFullTensor(n, 403));
    const Eigen::VectorXd k2 = shapedKappaSquared(n);
    const std::vector<int> held = {0, 1, 5};
    const FluidSystem forced(c, {k2, 0.02, 0.0, held});
    const FluidSystem free(c, {k2, 0.02, 0.0});
    Eigen::VectorXd v0 = Eigen::VectorXd::Zero(n);
    for (const int k : held) v0[k] = 1.0;  // all the energy in the held modes
    for (Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                              Integrator::Trapezoidal, Integrator::Linearized}) {
        ModalIntegrator integrator(forced, {scheme});
        ModalIntegrator unforced(free, {scheme});
        Eigen::VectorXd v = v0, w = v0;
        for (int s = 0; s < 400; ++s) {
            integrator.step(v, 0.01);
            unforced.step(w, 0.01);
        }
        for (const int k : held) EXPECT_EQ(v[k], v0[k]) << sceneKeyword(scheme) << ", mode " << k;
        double others = 0.0;
        for (int k = 0; k < n; ++k)
            if (std::find(held.begin(), held.end(), k) == held.end()) others += 0.5 * v[k] * v[k];
        EXPECT_GT(others, 1e-3) << sceneKeyword(scheme) << ": the held modes passed no energy on";
        // Without holding, viscosity and the exchange take energy from the same modes.
        EXPECT_LT(energy(w), energy(v0)) << sceneKeyword(scheme);
        EXPECT_GT(energy(v), energy(w)) << sceneKeyword(scheme);
    }
    EXPECT_THROW(FluidSystem(c, {k2, 0.0, 0.0, {n}}), Error);
}

TEST(Viscosity, EnergyFallsEveryStepAndAtLeastAtTheSlowestRate) {
    const int n = 30;
    const DenseCoefficients c = DenseCoefficients::fromFull(n, randomFullTensor(n, 402));
    const Eigen::VectorXd k2 = shapedKappaSquared(n);
    const double nu = 1e-3, h = 0.01;
    const FluidSystem system(c, {k2, nu, 0.0});
    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd v = randomVector(n, 403);
    const double e0 = energy(v), slowest = 2.0 * nu * k2.minCoeff();
    double previous = e0;
    for (int s = 1; s <= 500; ++s) {
        midpoint.step(v, h);
        ASSERT_LT(energy(v), previous) << "step " << s;
        ASSERT_LE(energy(v), e0 * std::exp(-slowest * s * h) * (1.0 + 1e-12)) << "step " << s;
        previous = energy(v);
    }
}

TEST(Viscosity, BadParametersThrow) {
    const DenseCoefficients c = DenseCoefficients::fromFull(4, randomFullTensor(4, 404));
    EXPECT_THROW(FluidSystem(c, {Eigen::VectorXd(), 0.1, 0.0}), Error);  // no κ²
    EXPECT_THROW(FluidSystem(c, {Eigen::VectorXd::Ones(3), 0.1, 0.0}), Error);
    EXPECT_THROW(FluidSystem(c, {Eigen::VectorXd::Ones(4), -0.1, 0.0}), Error);
    EXPECT_THROW(FluidSystem(c, {-Eigen::VectorXd::Ones(4), 0.1, 0.0}), Error);
}

}  // namespace
}  // namespace modeflow
