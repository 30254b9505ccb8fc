/// @file PseudoSpectralEulerTest.cpp
/// The full-spectrum reference of `modeflow validate`'s periodic experiment
/// (tools/validate/PseudoSpectralEuler.h) against flows whose face samples and evolution are known
/// in closed form: the staggered sampling (a half-cell shift on the wrong axis moves every sample),
/// the mean flow, the sign of the advection, and the energy it conserves.

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "tools/validate/PseudoSpectralEuler.h"

namespace modeflow::validate {
namespace {

constexpr int n = 32;
constexpr double length = 2.0 * std::numbers::pi, h = length / n;

/// u_x sampled at (i h, (j + ½) h), u_y at ((i + ½) h, j h): the periodic MAC grid's faces.
std::vector<double> faces(const std::function<double(double, double)>& ux,
                          const std::function<double(double, double)>& uy) {
    std::vector<double> f;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) f.push_back(ux(i * h, (j + 0.5) * h));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) f.push_back(uy((i + 0.5) * h, j * h));
    return f;
}

double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
    return worst;
}

TEST(PseudoSpectralEuler, ReadsAndSamplesADivergenceFreeFieldAtTheStaggeredFaces) {
    // u_x of y alone and u_y of x alone (divergence-free), with a mean flow.
    const std::vector<double> f =
        faces([](double, double y) { return 0.3 + 0.7 * std::cos(2 * y + 0.4); },
              [](double x, double) { return -0.2 + std::sin(3 * x); });
    PseudoSpectralEuler euler(n, length);
    euler.setFaceVelocity(f);
    const double error = maxDifference(euler.faceVelocity(), f);
    EXPECT_LT(error, 1e-12) << "max face difference " << error;
    // ½ ∫|u|² = ½ L² (0.3² + 0.7²/2 + 0.2² + 1/2).
    const double expected = 0.5 * length * length * (0.09 + 0.245 + 0.04 + 0.5);
    EXPECT_NEAR(euler.energy(), expected, 1e-10 * expected);
}

TEST(PseudoSpectralEuler, AMeanFlowCarriesAShearWave) {
    // u = (1, sin x): ω = cos x is carried along x at speed 1, so u_y(t) = sin(x − t).
    PseudoSpectralEuler euler(n, length);
    euler.setFaceVelocity(
        faces([](double, double) { return 1.0; }, [](double x, double) { return std::sin(x); }));
    for (int s = 0; s < 100; ++s) euler.step(0.01);
    const std::vector<double> expected = faces([](double, double) { return 1.0; },
                                               [](double x, double) { return std::sin(x - 1.0); });
    const double error = maxDifference(euler.faceVelocity(), expected);
    EXPECT_LT(error, 1e-8) << "max face difference at t = 1: " << error;
}

TEST(PseudoSpectralEuler, KeepsTheEnergyOfATurbulentFlow) {
    // Several interacting waves (not a steady flow): the dealiased dynamics conserve energy, RK4
    // up to its small dissipation.
    const auto ux = [](double x, double y) {
        return std::sin(2 * y) * std::cos(x) + 0.5 * std::cos(3 * y + 1);
    };
    const auto uy = [](double x, double y) {
        return 2 * std::sin(x) * std::cos(2 * y) - 0.4 * std::sin(4 * x);
    };
    PseudoSpectralEuler euler(n, length);
    euler.setFaceVelocity(faces(ux, uy));
    const double before = euler.energy();
    const std::vector<double> start = euler.faceVelocity();
    for (int s = 0; s < 200; ++s) euler.step(0.01);
    const double drift = std::abs(euler.energy() / before - 1.0);
    EXPECT_LT(drift, 1e-6) << "relative energy drift " << drift;
    EXPECT_GT(maxDifference(euler.faceVelocity(), start), 0.1) << "the flow did not evolve";
}

TEST(PseudoSpectralEuler, RefusesAFaceFieldOfAnotherGrid) {
    PseudoSpectralEuler euler(n, length);
    EXPECT_THROW(euler.setFaceVelocity(std::vector<double>(n * n)), std::exception);
    EXPECT_THROW(PseudoSpectralEuler(7, length), std::exception);
}

}  // namespace
}  // namespace modeflow::validate
