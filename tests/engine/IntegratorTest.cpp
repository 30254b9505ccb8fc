/// @file IntegratorTest.cpp
/// The time integrators on random antisymmetric C tensors and on the Euler top: conservation and
/// reversibility of the implicit rules (seed eqs. 6.8, 6.9), the measured energy growth of explicit
/// Euler, convergence orders, Newton behaviour, and forces.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/RandomCoefficients.h"

namespace modeflow {
namespace {

using testing::randomDense;
using testing::randomVector;

/// A step with h·|R(v)|/|v| = stiffness: the fraction of a "turnover" covered per step.
double stepFor(const StructuralCoefficients& c, const Eigen::VectorXd& v, double stiffness) {
    Eigen::VectorXd r;
    c.apply(v, v, r);
    return stiffness * v.norm() / r.norm();
}

struct RunSummary {
    double maxEnergyDrift = 0.0;  ///< max over steps of |E − E0| / E0
    int maxIterations = 0;
    double meanIterations = 0.0;
    double meanJacobians = 0.0;
    double maxResidual = 0.0;
    bool converged = true;
};

RunSummary run(ModalIntegrator& integrator, Eigen::VectorXd& v, double h, int steps) {
    RunSummary s;
    const double e0 = energy(v);
    long total = 0, jacobians = 0;
    for (int n = 0; n < steps; ++n) {
        const StepReport report = integrator.step(v, h);
        s.maxEnergyDrift = std::max(s.maxEnergyDrift, std::abs(energy(v) - e0) / e0);
        s.maxIterations = std::max(s.maxIterations, report.iterations);
        s.maxResidual = std::max(s.maxResidual, report.residual);
        s.converged = s.converged && report.converged;
        total += report.iterations;
        jacobians += report.jacobians;
    }
    s.meanIterations = double(total) / steps;
    s.meanJacobians = double(jacobians) / steps;
    return s;
}

class RandomState : public ::testing::Test {
protected:
    static constexpr int kModes = 50;
    DenseCoefficients mC = randomDense(kModes, 101);
    FluidSystem mSystem{mC};
    Eigen::VectorXd mV0 = randomVector(kModes, 202);
    double mH = stepFor(mC, mV0, 0.3);
};

TEST_F(RandomState, MidpointConservesEnergyAtALargeStep) {
    ModalIntegrator midpoint(mSystem, {Integrator::Midpoint});
    Eigen::VectorXd v = mV0;
    const RunSummary s = run(midpoint, v, mH, 10000);
    EXPECT_LE(s.maxEnergyDrift, 1e-10);
    EXPECT_LE(s.maxIterations, 8) << "mean " << s.meanIterations;
    EXPECT_GE(s.meanIterations, 1.0);
    EXPECT_LE(s.maxResidual, 1e-13);
    EXPECT_TRUE(s.converged);
    std::printf(
        "midpoint h|R|/|v| = 0.3, 1e4 steps: drift %.3g, Newton mean %.2f max %d, "
        "Jacobians mean %.2f\n",
        s.maxEnergyDrift, s.meanIterations, s.maxIterations, s.meanJacobians);
}

TEST_F(RandomState, NewtonKrylovMatchesTheDenseNewtonAndConservesEnergy) {
    // denseNewtonLimit = 0: nothing N² formed; fixed-point iterations at a small step, Newton–
    // Krylov once they stop contracting (the large step), to the same tolerance.
    IntegratorSettings krylov{Integrator::Midpoint};
    krylov.denseNewtonLimit = 0;
    const double small = stepFor(mC, mV0, 0.05);
    for (Integrator scheme : {Integrator::Midpoint, Integrator::Trapezoidal}) {
        krylov.scheme = scheme;
        for (const auto& [h, expected] :
             {std::pair{small, NewtonSolver::FixedPoint}, std::pair{mH, NewtonSolver::Krylov}}) {
            ModalIntegrator dense(mSystem, {scheme}), matrixFree(mSystem, krylov);
            Eigen::VectorXd a = mV0, b = mV0;
            const StepReport first = dense.step(a, h);
            const StepReport second = matrixFree.step(b, h);
            EXPECT_EQ(first.solver, NewtonSolver::DenseLu);
            EXPECT_EQ(second.solver, expected) << sceneKeyword(scheme) << ", h " << h;
            EXPECT_EQ(second.jacobianProducts > 0, expected == NewtonSolver::Krylov);
            EXPECT_EQ(second.jacobians, 0);
            EXPECT_TRUE(second.converged);
            EXPECT_LE((a - b).norm(), 1e-13 * a.norm()) << sceneKeyword(scheme) << ", h " << h;
        }
    }
    krylov.scheme = Integrator::Midpoint;
    ModalIntegrator midpoint(mSystem, krylov);
    Eigen::VectorXd v = mV0;
    const RunSummary s = run(midpoint, v, mH, 2000);
    EXPECT_LE(s.maxEnergyDrift, 1e-10);
    EXPECT_LE(s.maxResidual, 1e-13);
    EXPECT_TRUE(s.converged);
    std::printf(
        "matrix-free midpoint, h|R|/|v| = 0.3, 2000 steps: drift %.3g, iterations mean %.2f max "
        "%d\n",
        s.maxEnergyDrift, s.meanIterations, s.maxIterations);
}

/// FluidSystem counting its evaluations of R (full contractions).
class CountingSystem final : public ModalSystem {
public:
    explicit CountingSystem(const FluidSystem& system) : mSystem(system) {}
    int dimension() const override { return mSystem.dimension(); }
    const Eigen::VectorXd& mass() const override { return mSystem.mass(); }
    const Eigen::VectorXd& decayRates() const override { return mSystem.decayRates(); }
    void rhs(const Eigen::VectorXd& x, Eigen::VectorXd& out) const override {
        ++evaluations;
        mSystem.rhs(x, out);
    }
    void linearize(const Eigen::VectorXd& x, Eigen::VectorXd& out,
                   Eigen::MatrixXd& jacobian) const override {
        mSystem.linearize(x, out, jacobian);
    }
    void jacobianProduct(const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                         Eigen::VectorXd& out) const override {
        mSystem.jacobianProduct(x, u, out);
    }
    bool freezesRhs() const override { return true; }
    void frozenRhs(const Eigen::VectorXd& p, const Eigen::VectorXd& u,
                   Eigen::VectorXd& out) const override {
        mSystem.frozenRhs(p, u, out);
    }
    mutable int evaluations = 0;

private:
    const FluidSystem& mSystem;
};

TEST_F(RandomState, LinearizedConservesEnergyWithOnePassAndALinearSolve) {
    // The rule freezes R's first factor at an explicit predictor, so each step is one linear
    // solve with L(x~) (one contraction of the coefficients, then its second half per GMRES
    // product on the device); the predictor's rate is held from the step before, so R itself is
    // evaluated for the first step only. L(x~) is antisymmetric, so the energy is kept to the
    // solver's tolerance, as by the midpoint rule.
    const CountingSystem counting(mSystem);
    ModalIntegrator linearized(counting, {Integrator::Linearized});
    Eigen::VectorXd v = mV0;
    const double e0 = energy(v);
    double drift = 0.0, residual = 0.0;
    int products = 0;
    bool converged = true;
    for (int n = 0; n < 10000; ++n) {
        const StepReport report = linearized.step(v, mH);
        drift = std::max(drift, std::abs(energy(v) - e0) / e0);
        residual = std::max(residual, report.residual);
        products = std::max(products, report.jacobianProducts);
        converged = converged && report.converged;
        EXPECT_EQ(report.iterations, 1);
        EXPECT_EQ(report.solver, NewtonSolver::Krylov);
    }
    EXPECT_EQ(counting.evaluations, 1) << "R evaluated after the first step";
    EXPECT_EQ(linearized.heldRate().size(), kModes);
    EXPECT_LE(drift, 1e-10);
    EXPECT_LE(residual, 1e-13);
    EXPECT_TRUE(converged);
    EXPECT_LE(products, 30);
    std::printf("linearized h|R|/|v| = 0.3, 1e4 steps: drift %.3g, GMRES products max %d\n", drift,
                products);

    // A step is the midpoint step up to O(h³), from R(x) (the first step) as from the rate held
    // (the second): halving h cuts both differences eightfold.
    std::vector<double> firstGaps, secondGaps;
    for (const double h : {0.1 * mH, 0.05 * mH}) {
        ModalIntegrator midpoint(mSystem, {Integrator::Midpoint}),
            fresh(mSystem, {Integrator::Linearized});
        Eigen::VectorXd a = mV0, b = mV0;
        midpoint.step(a, h);
        fresh.step(b, h);
        firstGaps.push_back((a - b).norm());
        a = b;
        midpoint.step(a, h);
        fresh.step(b, h);
        secondGaps.push_back((a - b).norm());
    }
    for (const auto* gaps : {&firstGaps, &secondGaps})
        EXPECT_NEAR(std::log2((*gaps)[0] / (*gaps)[1]), 3.0, 0.25)
            << (*gaps)[0] << " -> " << (*gaps)[1];
}

TEST_F(RandomState, LinearizedRateRestoredContinuesBitForBitAndDroppedStartsFromR) {
    ModalIntegrator first(mSystem, {Integrator::Linearized});
    Eigen::VectorXd v = mV0;
    EXPECT_EQ(first.heldRate().size(), 0);
    for (int n = 0; n < 5; ++n) first.step(v, mH);
    // A second integrator given the state and the held rate (a resumed run) steps alike.
    ModalIntegrator resumed(mSystem, {Integrator::Linearized});
    resumed.setHeldRate(first.heldRate());
    Eigen::VectorXd w = v;
    for (int n = 0; n < 5; ++n) {
        first.step(v, mH);
        resumed.step(w, mH);
    }
    EXPECT_EQ(v, w);
    // Dropped, the next step starts from R(x) as a fresh integrator's does.
    ModalIntegrator fresh(mSystem, {Integrator::Linearized});
    Eigen::VectorXd u = v;
    first.dropHeldRate();
    first.step(v, mH);
    fresh.step(u, mH);
    EXPECT_EQ(v, u);
    EXPECT_THROW(first.setHeldRate(Eigen::VectorXd::Zero(kModes + 1)), Error);
    EXPECT_THROW(first.setHeldRate(Eigen::VectorXd::Constant(kModes, NAN)), Error);
    ModalIntegrator midpoint(mSystem, {Integrator::Midpoint});
    EXPECT_THROW(midpoint.setHeldRate(first.heldRate()), Error);
    midpoint.setHeldRate(Eigen::VectorXd());  // dropping is always allowed
}

TEST(Integrators, LinearizedRuleKeepsTheFilteredEnergyAndRefusesMhd) {
    // LANS-α: L(x~)·u = C(M x~, u) keeps ½ uᵀMu for any predictor.
    const DenseCoefficients c = randomDense(16, 106);
    FluidParameters lans;
    lans.alpha = 0.4;
    lans.kappaSquared = randomVector(16, 17).cwiseAbs() * 10.0;
    const FluidSystem filtered(c, lans);
    ModalIntegrator integrator(filtered, {Integrator::Linearized});
    Eigen::VectorXd v = randomVector(16, 18);
    const auto filteredEnergy = [&](const Eigen::VectorXd& x) {
        return 0.5 * x.dot(filtered.mass().cwiseProduct(x));
    };
    const double e0 = filteredEnergy(v), h = stepFor(c, v, 0.2);
    for (int n = 0; n < 1000; ++n) integrator.step(v, h);
    EXPECT_LE(std::abs(filteredEnergy(v) - e0), 1e-11 * e0);
    EXPECT_GT((v - randomVector(16, 18)).norm(), 0.1 * v.norm()) << "the state must move";

    const MhdSystem mhd(c);
    try {
        ModalIntegrator refused(mhd, {Integrator::Linearized});
        ADD_FAILURE() << "MHD took the linearized rule";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the linearized rule is for fluids"),
                  std::string::npos)
            << e.what();
    }
}

/// Steps forward then back with −h; the relative distance from the start.
double roundTrip(ModalIntegrator& integrator, const Eigen::VectorXd& v0, double h, int steps,
                 double& travelled) {
    Eigen::VectorXd v = v0;
    run(integrator, v, h, steps);
    travelled = (v - v0).norm() / v0.norm();
    run(integrator, v, -h, steps);
    return (v - v0).norm() / v0.norm();
}

TEST_F(RandomState, ImplicitRulesAreTimeReversible) {
    // A random quadratic system is chaotic, with a Lyapunov time of about one turnover |v|/|R|:
    // the 1e-16 round-off of each step grows like e^{t/turnover} on the way back, so the round
    // trips span ~10 turnovers (1000 small steps, or 30 large ones), enough to leave the start
    // far behind.
    const double small = stepFor(mC, mV0, 0.01);
    for (Integrator scheme : {Integrator::Midpoint, Integrator::Trapezoidal}) {
        ModalIntegrator integrator(mSystem, {scheme});
        for (const auto& [h, steps] : {std::pair{small, 1000}, std::pair{mH, 30}}) {
            double travelled = 0.0;
            const double back = roundTrip(integrator, mV0, h, steps, travelled);
            EXPECT_LE(back, 1e-9) << sceneKeyword(scheme) << ", " << steps << " steps";
            EXPECT_GT(travelled, 0.5) << "the round trip must actually move the state";
        }
    }
}

TEST_F(RandomState, TrapezoidalEnergyStaysBounded) {
    ModalIntegrator trapezoidal(mSystem, {Integrator::Trapezoidal});
    Eigen::VectorXd v = mV0;
    const double e0 = energy(v);
    const int steps = 10000, window = 1000;
    std::vector<double> e(steps);
    int maxIterations = 0;
    for (int n = 0; n < steps; ++n) {
        maxIterations = std::max(maxIterations, trapezoidal.step(v, mH).iterations);
        e[n] = energy(v) / e0 - 1.0;
    }
    const double maxDeviation = std::max(std::abs(*std::max_element(e.begin(), e.end())),
                                         std::abs(*std::min_element(e.begin(), e.end())));
    const double first = std::accumulate(e.begin(), e.begin() + window, 0.0) / window;
    const double last = std::accumulate(e.end() - window, e.end(), 0.0) / window;
    std::printf("trapezoidal: max |E/E0 - 1| %.3g, windowed means %.3g -> %.3g\n", maxDeviation,
                first, last);
    EXPECT_LE(maxDeviation, 0.05);
    EXPECT_LE(std::abs(last - first), 0.01) << "energy trend over 1e4 steps";
    EXPECT_LE(maxIterations, 8);
}

TEST_F(RandomState, ExplicitEulerEnergyGrowsWithTheStep) {
    // |v + hR|² = |v|² + h²|R|² since v·R = 0: explicit Euler gains energy every step, and over a
    // fixed time the gain is about proportional to h.
    const double time = 100 * mH;
    ModalIntegrator midpoint(mSystem, {Integrator::Midpoint});
    Eigen::VectorXd reference = mV0;
    const double midpointDrift = run(midpoint, reference, mH, 100).maxEnergyDrift;
    ModalIntegrator euler(mSystem, {Integrator::Explicit});
    std::vector<double> drifts;
    for (int refinement : {32, 64, 128}) {
        Eigen::VectorXd v = mV0;
        double previous = energy(v);
        bool monotone = true;
        for (int n = 0; n < 100 * refinement; ++n) {
            euler.step(v, time / (100 * refinement));
            monotone = monotone && energy(v) > previous;
            previous = energy(v);
        }
        drifts.push_back(energy(v) / energy(mV0) - 1.0);
        EXPECT_TRUE(monotone) << "h = mH/" << refinement;
        std::printf("explicit Euler h = h_mid/%d: energy drift %.3g over the run\n", refinement,
                    drifts.back());
    }
    EXPECT_GT(drifts[0], drifts[1]);
    EXPECT_GT(drifts[1], drifts[2]);
    EXPECT_GT(drifts[2], 1e3 * midpointDrift) << "midpoint drift " << midpointDrift;
    EXPECT_NEAR(drifts[1] / drifts[2], 2.0, 0.3) << "first order in h";
}

/// Error at time T of scheme with n steps against a fine RK4 reference.
double trajectoryError(const FluidSystem& system, Integrator scheme, const Eigen::VectorXd& v0,
                       double time, int steps, const Eigen::VectorXd& reference) {
    ModalIntegrator integrator(system, {scheme});
    Eigen::VectorXd v = v0;
    for (int n = 0; n < steps; ++n) integrator.step(v, time / steps);
    return (v - reference).norm() / reference.norm();
}

TEST(Integrators, ConvergeAtTheirOrders) {
    const DenseCoefficients c = randomDense(20, 103);
    const FluidSystem system(c);
    const Eigen::VectorXd v0 = randomVector(20, 204);
    const double time = 4 * stepFor(c, v0, 1.0);
    ModalIntegrator fine(system, {Integrator::Rk4});
    Eigen::VectorXd reference = v0;
    for (int n = 0; n < 4096; ++n) fine.step(reference, time / 4096);
    const std::vector<std::pair<Integrator, double>> orders{{Integrator::Rk4, 4.0},
                                                            {Integrator::Midpoint, 2.0},
                                                            {Integrator::Trapezoidal, 2.0},
                                                            {Integrator::Linearized, 2.0},
                                                            {Integrator::Explicit, 1.0}};
    for (const auto& [scheme, order] : orders) {
        const double coarse = trajectoryError(system, scheme, v0, time, 64, reference);
        const double finer = trajectoryError(system, scheme, v0, time, 128, reference);
        const double measured = std::log2(coarse / finer);
        EXPECT_NEAR(measured, order, 0.2)
            << sceneKeyword(scheme) << ": errors " << coarse << " -> " << finer;
    }
}

/// The Euler top: v̇ = (Λv) × v, i.e. C[k][i][j] = ε_kij λ_i, conserving |v|² and vᵀΛv.
DenseCoefficients eulerTop(const Eigen::Vector3d& lambda) {
    std::vector<double> full(27, 0.0);
    const int cyclic[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
    for (const auto& p : cyclic) {
        full[(p[0] * 3 + p[1]) * 3 + p[2]] = lambda[p[1]];   // ε = +1
        full[(p[0] * 3 + p[2]) * 3 + p[1]] = -lambda[p[2]];  // ε = −1
    }
    return DenseCoefficients::fromFull(3, full);
}

TEST(EulerTop, MidpointKeepsBothQuadraticInvariants) {
    const Eigen::Vector3d lambda(1.0, 2.0, 3.5);
    const DenseCoefficients c = eulerTop(lambda);
    const FluidSystem system(c);
    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd v(3);
    v << 0.3, 1.0, 0.2;
    const double e0 = v.squaredNorm(), q0 = v.dot(lambda.cwiseProduct(v));
    double worstE = 0.0, worstQ = 0.0;
    for (int n = 0; n < 10000; ++n) {
        midpoint.step(v, 0.2);
        worstE = std::max(worstE, std::abs(v.squaredNorm() / e0 - 1.0));
        worstQ = std::max(worstQ, std::abs(v.dot(lambda.cwiseProduct(v)) / q0 - 1.0));
    }
    EXPECT_LE(worstE, 1e-12);
    EXPECT_LE(worstQ, 1e-12);  // the midpoint rule keeps every quadratic invariant

    // The top is integrable, so errors grow slowly and even long round trips come back.
    for (Integrator scheme : {Integrator::Midpoint, Integrator::Trapezoidal}) {
        ModalIntegrator integrator(system, {scheme});
        double travelled = 0.0;
        EXPECT_LE(roundTrip(integrator, v, 0.2, 1000, travelled), 1e-10) << sceneKeyword(scheme);
        EXPECT_GT(travelled, 0.01);  // the orbit is periodic: 1000 steps end somewhere on it
    }
}

TEST(EulerTop, SymmetricTopMatchesClosedForms) {
    // λ0 = λ1 = a: v2 is constant and (v0, v1) rotates at ω = (a − λ2)v2, θ(t) = θ0 − ωt.
    // The midpoint rule applies the Cayley transform: exactly −2·atan(ωh/2) per step.
    const double a = 2.0, b = 0.5, v2 = 0.8, radius = 1.3, theta0 = 0.4, h = 0.25;
    const DenseCoefficients c = eulerTop({a, a, b});
    const FluidSystem system(c);
    const double omega = (a - b) * v2;
    Eigen::VectorXd v0(3);
    v0 << radius * std::cos(theta0), radius * std::sin(theta0), v2;

    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd v = v0;
    const int steps = 1000;
    for (int n = 0; n < steps; ++n) midpoint.step(v, h);
    const double theta = theta0 - 2.0 * steps * std::atan(0.5 * omega * h);
    Eigen::VectorXd expected(3);
    expected << radius * std::cos(theta), radius * std::sin(theta), v2;
    EXPECT_LT((v - expected).norm(), 1e-10) << "midpoint after " << steps << " steps";

    // RK4 against the exact solution at t = 2: fourth order.
    std::vector<double> errors;
    for (int steps4 : {20, 40}) {
        ModalIntegrator rk4(system, {Integrator::Rk4});
        Eigen::VectorXd w = v0;
        for (int n = 0; n < steps4; ++n) rk4.step(w, 2.0 / steps4);
        Eigen::VectorXd exact(3);
        exact << radius * std::cos(theta0 - 2.0 * omega), radius * std::sin(theta0 - 2.0 * omega),
            v2;
        errors.push_back((w - exact).norm());
    }
    EXPECT_NEAR(std::log2(errors[0] / errors[1]), 4.0, 0.1)
        << "errors " << errors[0] << " -> " << errors[1];
}

TEST(Forces, ConstantForceWithoutCouplingIsExactForEveryScheme) {
    const int n = 10;
    const DenseCoefficients zero(n, std::vector<double>(packedSize(n), 0.0));
    const FluidSystem system(zero);
    const Eigen::VectorXd v0 = randomVector(n, 301), f = randomVector(n, 302);
    const double h = 0.05;
    for (Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                              Integrator::Trapezoidal, Integrator::Linearized}) {
        ModalIntegrator integrator(system, {scheme});
        Eigen::VectorXd v = v0;
        for (int s = 0; s < 100; ++s) integrator.step(v, h, f);
        const Eigen::VectorXd expected = v0 + f * (100 * h);
        EXPECT_LT((v - expected).norm() / expected.norm(), 1e-13) << sceneKeyword(scheme);
    }
}

TEST(Forces, LinearInTimeForceIsExactForSecondOrderSchemes) {
    const int n = 8;
    const DenseCoefficients zero(n, std::vector<double>(packedSize(n), 0.0));
    const FluidSystem system(zero);
    const Eigen::VectorXd v0 = randomVector(n, 303), f0 = randomVector(n, 304),
                          f1 = randomVector(n, 305);
    const ForceFunction force = [&](double t) { return Eigen::VectorXd(f0 + t * f1); };
    const double h = 0.1;
    for (Integrator scheme :
         {Integrator::Rk4, Integrator::Midpoint, Integrator::Trapezoidal, Integrator::Linearized}) {
        ModalIntegrator integrator(system, {scheme});
        Eigen::VectorXd v = v0;
        double t = 1.0;
        for (int s = 0; s < 50; ++s, t += h) integrator.step(v, t, h, force);
        const Eigen::VectorXd expected = v0 + f0 * (t - 1.0) + 0.5 * f1 * (t * t - 1.0);
        EXPECT_LT((v - expected).norm() / expected.norm(), 1e-13) << sceneKeyword(scheme);
    }
}

TEST(Integrators, JacobianProductsEqualTheAnalyticJacobian) {
    const DenseCoefficients c = randomDense(12, 105);
    FluidParameters lans;
    lans.alpha = 0.3;
    lans.kappaSquared = randomVector(12, 7).cwiseAbs();
    const FluidSystem euler(c), filtered(c, lans);
    const MhdSystem mhd(c);
    for (const ModalSystem* system :
         std::initializer_list<const ModalSystem*>{&euler, &filtered, &mhd}) {
        const int n = system->dimension();
        const Eigen::VectorXd x = randomVector(n, 8), u = randomVector(n, 9);
        Eigen::VectorXd r, product;
        Eigen::MatrixXd jac;
        system->linearize(x, r, jac);
        system->jacobianProduct(x, u, product);
        EXPECT_LE((product - jac * u).norm(), 1e-13 * (jac * u).norm()) << "dimension " << n;
    }
}

TEST(Integrators, RejectBadInput) {
    const DenseCoefficients c = randomDense(6, 104);
    const FluidSystem system(c);
    ModalIntegrator integrator(system);
    Eigen::VectorXd wrong = Eigen::VectorXd::Ones(5), v = Eigen::VectorXd::Ones(6);
    EXPECT_THROW(integrator.step(wrong, 0.1), Error);
    EXPECT_THROW(integrator.step(v, 0.1, Eigen::VectorXd::Ones(7)), Error);
    EXPECT_THROW(ModalIntegrator(system, {Integrator::Midpoint, 0.0, 10}), Error);
    IntegratorSettings noRestart;
    noRestart.krylovRestart = 0;
    EXPECT_THROW(ModalIntegrator(system, noRestart), Error);
    EXPECT_EQ(parseIntegrator("trapezoidal", "--integrator"), Integrator::Trapezoidal);
    EXPECT_EQ(parseIntegrator("linearized", "--integrator"), Integrator::Linearized);
    EXPECT_EQ(sceneKeyword(parseIntegrator("rk4", "--integrator")), "rk4");
    EXPECT_THROW(parseIntegrator("leapfrog", "--integrator"), Error);
}

}  // namespace
}  // namespace modeflow
