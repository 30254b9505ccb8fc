/// @file ModalStepKernelTest.cpp
/// ModalStepper (the modal step on the device, float32) against the double-precision CPU
/// reference ModalIntegrator: single steps of every scheme with forces, viscosity and LANS-α;
/// tensor-free coefficients; MHD with every storage; trajectories; midpoint energy (and MHD's
/// cross helicity) conservation; warm starts; convergence reporting; split coefficients.

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/device/ModalStepper.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/LinearModalTerm.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/dynamics/TensorFreeCoefficients.h"
#include "engine/vulkan/CommandSequence.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/KernelTestSupport.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using testing::roundedDense;
using testing::roundedToFloat;

using device::DeviceStepSettings;
using device::ModalStepper;
using vulkan::CommandSequence;

constexpr int kModes = 40;

double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

/// A step with h·|R(v)|/|v| = stiffness: the fraction of a "turnover" covered per step.
double stepFor(const StructuralCoefficients& c, const Eigen::VectorXd& v, double stiffness) {
    Eigen::VectorXd r;
    c.apply(v, v, r);
    return stiffness * v.norm() / r.norm();
}

/// `steps` steps on the device in one submission.
void runDevice(const vulkan::VulkanContext& context, const ModalStepper& stepper, double h,
               int steps) {
    CommandSequence sequence(context);
    for (int s = 0; s < steps; ++s) stepper.recordStep(sequence, h);
    sequence.submitAndWait();
}

class ModalStepKernelTest : public testing::VulkanTest {
protected:
    DenseCoefficients mC = roundedDense(testing::randomDense(kModes, 11));
    Eigen::VectorXd mV0 = roundedToFloat(testing::randomVector(kModes, 12));
    /// 0.02 of a turnover per step, so 200 steps span 4 turnovers: random coefficient tensors are
    /// strongly chaotic, and float32 round-off (1e-7 per step) grows about e-fold per turnover.
    double mH = stepFor(mC, mV0, 0.02);

    /// `parameters` and the same with viscous LANS-α: the two cases of the every-scheme tests.
    static std::array<FluidParameters, 2> withViscousLans(const FluidParameters& parameters) {
        FluidParameters lans = parameters;
        lans.kappaSquared = testing::shapedKappaSquared(kModes) / 100.0;
        lans.viscosity = 0.05;
        lans.alpha = 0.1;
        return {parameters, lans};
    }
    /// 10 CPU-reference steps of `parameters` from mV0 in `scheme`.
    Eigen::VectorXd cpuSteps(const FluidParameters& parameters, Integrator scheme) const {
        const FluidSystem system(mC, parameters);
        ModalIntegrator cpu(system, {scheme});
        Eigen::VectorXd v = mV0;
        for (int s = 0; s < 10; ++s) cpu.step(v, mH);
        return v;
    }
};

TEST_P(ModalStepKernelTest, OneStepOfEverySchemeEqualsTheCpuReference) {
    FluidParameters viscousLans;
    viscousLans.kappaSquared = testing::shapedKappaSquared(kModes) / 100.0;
    viscousLans.viscosity = 0.05;
    viscousLans.alpha = 0.1;
    const Eigen::VectorXd force = roundedToFloat(0.3 * testing::randomVector(kModes, 13));
    for (const FluidParameters& parameters : {FluidParameters{}, viscousLans}) {
        const FluidSystem system(mC, parameters);
        for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                        Integrator::Trapezoidal, Integrator::Linearized}) {
            ModalIntegrator cpu(system, {scheme});
            Eigen::VectorXd expected = mV0;
            cpu.step(expected, mH, force);
            {
                ModalStepper stepper(context(), mC, parameters, {scheme});
                stepper.setState(mV0);
                stepper.setForce(force);
                runDevice(context(), stepper, mH, 1);
                const double error = relativeDifference(stepper.state(), expected);
                std::cout << sceneKeyword(scheme)
                          << (parameters.alpha > 0 ? " viscous LANS" : " Euler")
                          << ": relative error " << error << ", iterations "
                          << stepper.status().iterations << "\n";
                EXPECT_LE(error, 1e-5) << sceneKeyword(scheme);
                EXPECT_TRUE(stepper.status().converged);
            }
            expectNoValidationMessages();
        }
    }
}

/// A linear term D v given as its matrix (a wind's term, WindTransport, is one such).
class MatrixTerm final : public LinearModalTerm {
public:
    explicit MatrixTerm(Eigen::MatrixXd d) : mD(std::move(d)) {}
    int size() const override { return int(mD.rows()); }
    void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const override { out = mD * v; }
    const Eigen::MatrixXd& matrix() const override { return mD; }

private:
    Eigen::MatrixXd mD;
};

/// A random D of float-exact entries, as strong as the contraction at `v` (|D v| ≈ |C(v, v)|),
/// and not antisymmetric (a wind takes energy out).
std::shared_ptr<const LinearModalTerm> randomTerm(const StructuralCoefficients& c,
                                                  const Eigen::VectorXd& v, unsigned seed) {
    const int n = c.size();
    Eigen::MatrixXd d(n, n);
    for (int j = 0; j < n; ++j) d.col(j) = testing::randomVector(n, seed + unsigned(j));
    Eigen::VectorXd r;
    c.apply(v, v, r);
    d *= r.norm() / (d * v).norm();
    return std::make_shared<MatrixTerm>(d.cast<float>().cast<double>());
}

TEST_P(ModalStepKernelTest, HeldModesStepLikeTheCpuReferenceInEveryScheme) {
    // [forcing]: held modes keep their amplitude (rate and decay 0) while they drive the others.
    FluidParameters held;
    held.held = {0, 3, 7};
    for (const FluidParameters& parameters : withViscousLans(held)) {
        for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                        Integrator::Trapezoidal, Integrator::Linearized}) {
            const Eigen::VectorXd expected = cpuSteps(parameters, scheme);
            ModalStepper stepper(context(), mC, parameters, {scheme});
            stepper.setState(mV0);
            runDevice(context(), stepper, mH, 10);
            const Eigen::VectorXd state = stepper.state();
            EXPECT_LE(relativeDifference(state, expected), 1e-5) << sceneKeyword(scheme);
            for (const int k : parameters.held)
                EXPECT_EQ(state[k], mV0[k]) << sceneKeyword(scheme) << ": held mode " << k;
            EXPECT_GT((state - mV0).norm(), 1e-2 * mV0.norm()) << "nothing moved";
            EXPECT_EQ(stepper.status().unconvergedSteps, 0);
            expectNoValidationMessages();
        }
    }
}

TEST_P(ModalStepKernelTest, ALinearTermStepsLikeTheCpuReferenceInEveryScheme) {
    // R(v) = C(v, v) + D v (a wind): the device adds D y to every evaluation, and to the
    // linearized rule's frozen L(x~) y, whose Jacobian part it is.
    FluidParameters windy;
    windy.linear = randomTerm(mC, mV0, 31);
    for (const FluidParameters& parameters : withViscousLans(windy)) {
        for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                        Integrator::Trapezoidal, Integrator::Linearized}) {
            const Eigen::VectorXd expected = cpuSteps(parameters, scheme);
            {
                ModalStepper stepper(context(), mC, parameters, {scheme});
                stepper.setState(mV0);
                runDevice(context(), stepper, mH, 10);
                const double error = relativeDifference(stepper.state(), expected);
                std::cout << sceneKeyword(scheme)
                          << (parameters.alpha > 0 ? " viscous LANS" : " Euler")
                          << " with a linear term, 10 steps: relative error " << error << "\n";
                EXPECT_LE(error, 1e-5) << sceneKeyword(scheme);
                EXPECT_EQ(stepper.status().unconvergedSteps, 0);
            }
            expectNoValidationMessages();
        }
    }
    // Tensor-free coefficients contract in their own dispatches; the term follows them.
    const BasisCache cache = testing::withDeviceModes(testing::disk2d(), ModePrecision::Float32);
    const TensorFreeCoefficients free(cache.velocity.modes, cache.quadrature);
    const Eigen::VectorXd v0 = roundedToFloat(testing::randomVector(free.size(), 14));
    const double h = stepFor(free, v0, 0.05);
    FluidParameters freeWindy;
    freeWindy.linear = randomTerm(free, v0, 41);
    for (const Integrator scheme : {Integrator::Midpoint, Integrator::Linearized}) {
        const FluidSystem system(free, freeWindy);
        ModalIntegrator cpu(system, {scheme});
        Eigen::VectorXd expected = v0;
        for (int s = 0; s < 10; ++s) cpu.step(expected, h);
        ModalStepper stepper(context(), free, freeWindy, {scheme}, &cache);
        stepper.setState(v0);
        runDevice(context(), stepper, h, 10);
        EXPECT_LE(relativeDifference(stepper.state(), expected), 1e-5)
            << "tensor-free " << sceneKeyword(scheme);
    }
    // The term changes what the steps do (not a test that passes without it), and a stepper
    // whose parameters drop it steps as one made without it.
    ModalStepper windless(context(), mC, FluidParameters{}), dropped(context(), mC, windy);
    dropped.setParameters(FluidParameters{});
    for (ModalStepper* stepper : {&windless, &dropped}) {
        stepper->setState(mV0);
        runDevice(context(), *stepper, mH, 10);
    }
    const FluidSystem windySystem(mC, windy);
    ModalIntegrator cpu(windySystem, {Integrator::Midpoint});
    Eigen::VectorXd withWind = mV0;
    for (int s = 0; s < 10; ++s) cpu.step(withWind, mH);
    EXPECT_GT(relativeDifference(windless.state(), withWind), 1e-2);
    EXPECT_EQ(dropped.state(), windless.state());
    // A term for another basis is refused by name.
    FluidParameters wrong;
    wrong.linear = std::make_shared<MatrixTerm>(Eigen::MatrixXd::Zero(kModes + 1, kModes + 1));
    try {
        ModalStepper refused(context(), mC, wrong);
        ADD_FAILURE() << "a linear term of another size was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("linear term of 41 modes"), std::string::npos)
            << e.what();
    }
}

TEST_P(ModalStepKernelTest, SparseCoefficientsStepLikeDenseOnes) {
    const DenseCoefficients dense = roundedDense(testing::randomDense(kModes, 21, 0.1));
    const SparseCoefficients sparse = SparseCoefficients::fromDense(dense);
    const double h = stepFor(dense, mV0, 0.1);
    for (const Integrator scheme : {Integrator::Midpoint, Integrator::Linearized}) {
        ModalStepper fromDense(context(), dense, {}, {scheme}),
            fromSparse(context(), sparse, {}, {scheme});
        for (ModalStepper* stepper : {&fromDense, &fromSparse}) {
            stepper->setState(mV0);
            runDevice(context(), *stepper, h, 5);
        }
        EXPECT_LE(relativeDifference(fromSparse.state(), fromDense.state()), 1e-6)
            << sceneKeyword(scheme);
    }
}

TEST_P(ModalStepKernelTest, TensorFreeCoefficientsStepLikeTheCpuReference) {
    // A real basis (the quadrature lives in it), its modes as the device holds them.
    const BasisCache cache = testing::withDeviceModes(testing::disk2d(), ModePrecision::Float32);
    const TensorFreeCoefficients c(cache.velocity.modes, cache.quadrature);
    const int n = c.size();
    FluidParameters lans;
    lans.kappaSquared = cache.velocity.eigenvalues;
    lans.viscosity = 1e-3;
    lans.alpha = 0.05;
    const Eigen::VectorXd v0 = roundedToFloat(testing::randomVector(n, 14));
    const double h = stepFor(c, v0, 0.05);
    for (const FluidParameters& parameters : {FluidParameters{}, lans}) {
        const FluidSystem system(c, parameters);
        for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                        Integrator::Trapezoidal, Integrator::Linearized}) {
            ModalIntegrator cpu(system, {scheme});
            Eigen::VectorXd expected = v0;
            for (int s = 0; s < 20; ++s) cpu.step(expected, h);
            {
                ModalStepper stepper(context(), c, parameters, {scheme}, &cache);
                ASSERT_TRUE(stepper.coefficients().isTensorFree());
                stepper.setState(v0);
                stepper.setForce(Eigen::VectorXd::Zero(n));
                runDevice(context(), stepper, h, 20);
                const double error = relativeDifference(stepper.state(), expected);
                std::cout << sceneKeyword(scheme)
                          << (parameters.alpha > 0 ? " viscous LANS" : " Euler")
                          << ", tensor-free, 20 steps: relative error " << error << "\n";
                EXPECT_LE(error, 1e-5) << sceneKeyword(scheme);
            }
            expectNoValidationMessages();
        }
    }
    // Made for Euler, switched to LANS-α: C(v, v) becomes C(Mv, v), with other dispatches.
    const FluidSystem system(c, lans);
    ModalIntegrator cpu(system, {Integrator::Midpoint});
    Eigen::VectorXd expected = v0;
    for (int s = 0; s < 20; ++s) cpu.step(expected, h);
    ModalStepper stepper(context(), c, FluidParameters{}, {Integrator::Midpoint}, &cache);
    stepper.setParameters(lans);
    stepper.setState(v0);
    stepper.setForce(Eigen::VectorXd::Zero(n));
    runDevice(context(), stepper, h, 20);
    EXPECT_LE(relativeDifference(stepper.state(), expected), 1e-5) << "switched to LANS-α";
}

TEST_P(ModalStepKernelTest, TrajectoriesStayWithin1e4OfTheDoubleReference) {
    const FluidSystem system(mC);
    for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                    Integrator::Trapezoidal, Integrator::Linearized}) {
        ModalIntegrator cpu(system, {scheme});
        {
            ModalStepper stepper(context(), mC, {}, {scheme});
            stepper.setState(mV0);
            Eigen::VectorXd expected = mV0;
            double worst = 0.0;
            for (int block = 0; block < 10; ++block) {  // 200 steps, compared every 20
                for (int s = 0; s < 20; ++s) cpu.step(expected, mH);
                runDevice(context(), stepper, mH, 20);
                worst = std::max(worst, relativeDifference(stepper.state(), expected));
            }
            std::cout << sceneKeyword(scheme) << ": max relative deviation over 200 steps " << worst
                      << "\n";
            EXPECT_LE(worst, 1e-4) << sceneKeyword(scheme);
        }
    }
}

/// The largest relative energy drift over 1000 steps of h from v0, checked every 100, and the
/// most iterations the last step of a block took.
std::pair<double, int> driftOver1000Steps(const vulkan::VulkanContext& context,
                                          ModalStepper& stepper, const Eigen::VectorXd& v0,
                                          double h) {
    stepper.setState(v0);
    const double e0 = energy(v0);
    double drift = 0.0;
    int maxIterations = 0;
    for (int block = 0; block < 10; ++block) {
        runDevice(context, stepper, h, 100);
        drift = std::max(drift, std::abs(energy(stepper.state()) - e0) / e0);
        maxIterations = std::max(maxIterations, stepper.status().iterations);
    }
    return {drift, maxIterations};
}

TEST_P(ModalStepKernelTest, MidpointConservesEnergyOver1000Steps) {
    const double h = stepFor(mC, mV0, 0.3);  // the CPU tests' large step
    {
        ModalStepper stepper(context(), mC, {});
        const double drift = driftOver1000Steps(context(), stepper, mV0, h).first;
        std::cout << "midpoint, 1000 steps of h|R|/|v| = 0.3: energy drift " << drift
                  << ", last step " << stepper.status().iterations << " iterations\n";
        EXPECT_LE(drift, 1e-5);
        EXPECT_EQ(stepper.status().unconvergedSteps, 0);
    }
}

TEST_P(ModalStepKernelTest, LinearizedConservesEnergyOver1000Steps) {
    // Its iterations solve a linear system whose operator is antisymmetric: the energy is kept
    // to the iteration's tolerance, as by the midpoint rule, from pair sums made once a step
    // (twice for the first, whose predictor evaluates R).
    const double h = stepFor(mC, mV0, 0.3);
    {
        ModalStepper stepper(context(), mC, {}, {Integrator::Linearized});
        // Begin, R(x) and the predictor, one set of pair sums, 30 iterations of two combines and
        // an update, end.
        const std::size_t pairSums = stepper.coefficients().pairSumGroups().size();
        EXPECT_EQ(stepper.dispatchesPerStep(), 1 + (pairSums + 3) + pairSums + 30 * 3 + 1);
        const auto [drift, maxIterations] = driftOver1000Steps(context(), stepper, mV0, h);
        std::cout << "linearized, 1000 steps of h|R|/|v| = 0.3: energy drift " << drift
                  << ", at most " << maxIterations << " iterations a step\n";
        EXPECT_LE(drift, 1e-5);
        EXPECT_EQ(stepper.status().unconvergedSteps, 0);
        EXPECT_GT(relativeDifference(stepper.state(), mV0), 0.1) << "the state must move";
    }
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, SwitchingToAndFromTheLinearizedRuleStepsLikeAFreshStepper) {
    // The iterations dispatch other kernels (combines alone): setIntegrator rebuilds their
    // arguments.
    const double h = stepFor(mC, mV0, 0.1);
    {
        ModalStepper switched(context(), mC, {}, {Integrator::Midpoint});
        switched.setState(mV0);
        runDevice(context(), switched, h, 3);
        const Eigen::VectorXd middle = switched.state();
        switched.setIntegrator(Integrator::Linearized);
        runDevice(context(), switched, h, 3);
        ModalStepper fresh(context(), mC, {}, {Integrator::Linearized});
        fresh.setState(middle);
        runDevice(context(), fresh, h, 3);
        EXPECT_LE(relativeDifference(switched.state(), fresh.state()), 1e-6);
        switched.setIntegrator(Integrator::Midpoint);
        runDevice(context(), switched, h, 3);
        EXPECT_TRUE(switched.status().converged);
        EXPECT_GT(switched.status().iterations, 0);
    }
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, LinearizedStepsHoldTheCpusRateAndUseIt) {
    // After the first step the predictor's rate is the one held from the step before, as on the
    // CPU: the device holds the CPU's rate, and a step from a restored rate is the CPU's step.
    const double h = stepFor(mC, mV0, 0.3);
    const Eigen::VectorXd force = roundedToFloat(0.3 * testing::randomVector(kModes, 19));
    const FluidSystem system(mC);
    ModalIntegrator cpu(system, {Integrator::Linearized});
    Eigen::VectorXd expected = mV0;
    {
        ModalStepper stepper(context(), mC, {}, {Integrator::Linearized});
        stepper.setState(mV0);
        stepper.setForce(force);
        EXPECT_EQ(stepper.heldRate().size(), 0);
        for (int s = 0; s < 4; ++s) cpu.step(expected, h, force);
        runDevice(context(), stepper, h, 4);
        EXPECT_LE(relativeDifference(stepper.state(), expected), 1e-5);
        EXPECT_LE(relativeDifference(stepper.heldRate(), cpu.heldRate()), 1e-4);

        // From the CPU's state and rate the device takes the CPU's step; from another rate, not.
        const Eigen::VectorXd x = roundedToFloat(expected), g = roundedToFloat(cpu.heldRate());
        cpu.setHeldRate(g);
        Eigen::VectorXd next = x;
        cpu.step(next, h, force);
        stepper.setState(x);
        EXPECT_EQ(stepper.heldRate().size(), 0) << "a state from the host drops the rate";
        stepper.setHeldRate(g);
        EXPECT_EQ(stepper.heldRate(), g.cast<float>().cast<double>());
        runDevice(context(), stepper, h, 1);
        EXPECT_LE(relativeDifference(stepper.state(), next), 1e-5);
        stepper.setState(x);
        stepper.setHeldRate(Eigen::VectorXd::Zero(kModes));
        runDevice(context(), stepper, h, 1);
        EXPECT_GT(relativeDifference(stepper.state(), next), 1e-3) << "the rate held is used";

        EXPECT_THROW(stepper.setHeldRate(Eigen::VectorXd::Zero(kModes + 1)), Error);
        EXPECT_THROW(stepper.setHeldRate(Eigen::VectorXd::Constant(kModes, NAN)), Error);
        stepper.setIntegrator(Integrator::Midpoint);
        EXPECT_EQ(stepper.heldRate().size(), 0);
        EXPECT_THROW(stepper.setHeldRate(g), Error);
    }
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, AccelerationCutsTheIterationsOfLargeSteps) {
    // A step of h|R|/|v| = 0.7: the plain fixed-point iteration contracts slowly there (the
    // advection Jacobian's eigenvalues are nearly imaginary), Anderson's directions fast; both
    // reach the same fixed point, the CPU reference's.
    const double h = stepFor(mC, mV0, 0.7);
    const FluidSystem system(mC, {});
    for (const Integrator scheme : {Integrator::Midpoint, Integrator::Trapezoidal}) {
        ModalIntegrator cpu(system, {scheme});
        Eigen::VectorXd expected = mV0;
        cpu.step(expected, h, Eigen::VectorXd::Zero(kModes));
        int iterations[2] = {0, 0};
        for (const bool accelerated : {false, true}) {
            DeviceStepSettings settings{scheme};
            settings.maxIterations = 200;
            settings.accelerated = accelerated;
            ModalStepper stepper(context(), mC, {}, settings);
            stepper.setState(mV0);
            runDevice(context(), stepper, h, 1);
            ASSERT_TRUE(stepper.status().converged) << sceneKeyword(scheme) << accelerated;
            iterations[accelerated] = stepper.status().iterations;
            EXPECT_LE(relativeDifference(stepper.state(), expected), 1e-5)
                << sceneKeyword(scheme) << (accelerated ? " accelerated" : " plain");
        }
        std::cout << sceneKeyword(scheme) << ", h|R|/|v| = 0.7: " << iterations[0]
                  << " plain iterations, " << iterations[1] << " accelerated\n";
        EXPECT_LE(2 * iterations[1], iterations[0]) << sceneKeyword(scheme);
    }
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, WarmStartsCutTheIterationsOfATrajectory) {
    // 20 forced steps of 0.1 of a turnover: started from R extrapolated from the last steps,
    // a midpoint step needs fewer evaluations than from y = x, and reaches the same states.
    const double h = stepFor(mC, mV0, 0.1);
    const Eigen::VectorXd force = roundedToFloat(0.3 * testing::randomVector(kModes, 13));
    constexpr int kSteps = 20;
    Eigen::VectorXd states[2];
    int iterations[2] = {0, 0};
    for (const bool warm : {false, true}) {
        DeviceStepSettings settings;
        settings.warmStart = warm;
        ModalStepper stepper(context(), mC, {}, settings);
        stepper.setState(mV0);
        stepper.setForce(force);
        for (int s = 0; s < kSteps; ++s) {
            runDevice(context(), stepper, h, 1);
            ASSERT_TRUE(stepper.status().converged) << "step " << s << (warm ? " warm" : " cold");
            iterations[warm] += stepper.status().iterations;
        }
        states[warm] = stepper.state();
    }
    std::cout << kSteps << " midpoint steps of h|R|/|v| = 0.1: " << iterations[0]
              << " iterations from y = x, " << iterations[1] << " warm\n";
    EXPECT_LE(relativeDifference(states[1], states[0]), 1e-5);
    EXPECT_LE(iterations[1] + kSteps / 2, iterations[0]);
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, AStateWrittenFromTheHostStartsCold) {
    // The R held from earlier steps is not R near a new state: the step after setState is the
    // step of a fresh stepper, to the bit.
    ModalStepper stepper(context(), mC, {});
    stepper.setState(roundedToFloat(testing::randomVector(kModes, 14)));
    for (int s = 0; s < 3; ++s) runDevice(context(), stepper, mH, 1);
    stepper.setState(mV0);
    runDevice(context(), stepper, mH, 1);
    ModalStepper fresh(context(), mC, {});
    fresh.setState(mV0);
    runDevice(context(), fresh, mH, 1);
    EXPECT_EQ(stepper.status().iterations, fresh.status().iterations);
    EXPECT_EQ(relativeDifference(stepper.state(), fresh.state()), 0.0);
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, AWarmStartRestoredContinuesToTheBit) {
    // What a checkpoint saves of a midpoint run on the device (the R of the last converged steps)
    // and a resumed run restores: a fresh stepper given the state and that warm start takes the
    // steps of the one that never stopped, to the bit, after one step (one R held) and after
    // several (two), for a fluid and for MHD with the Lorentz force (r less its Lorentz part).
    const Eigen::VectorXd force = roundedToFloat(0.3 * testing::randomVector(kModes, 13));
    const MhdParameters mhd{testing::shapedKappaSquared(kModes) / 100.0, 0.02, 0.03};
    const MhdSystem mhdSystem(mC, mhd);
    const Eigen::VectorXd mhdStart = roundedToFloat(mhdSystem.state(
        testing::randomVector(kModes, 61), 0.5 * testing::randomVector(kModes, 62)));
    for (const bool magnetic : {false, true}) {
        for (const int before : {1, 2, 5}) {
            const device::DeviceModel model =
                magnetic ? device::DeviceModel(mhd) : device::DeviceModel(FluidParameters{});
            ModalStepper whole(context(), mC, model, {});
            whole.setState(magnetic ? mhdStart : mV0);
            whole.setForce(force);
            runDevice(context(), whole, mH, before);
            const std::vector<Eigen::VectorXd> warm = whole.warmStart();
            ASSERT_EQ(warm.size(), std::size_t(std::min(before, 2)));
            EXPECT_EQ(warm[0].size(), whole.dimension());
            ModalStepper resumed(context(), mC, model, {});
            resumed.setState(whole.state());
            resumed.setForce(force);
            EXPECT_TRUE(resumed.warmStart().empty()) << "a state from the host starts cold";
            resumed.setWarmStart(warm);
            EXPECT_EQ(resumed.warmStart(), warm) << "the warm start reads back as it was set";
            runDevice(context(), whole, mH, 3);
            runDevice(context(), resumed, mH, 3);
            EXPECT_EQ(resumed.status().iterations, whole.status().iterations);
            EXPECT_EQ(relativeDifference(resumed.state(), whole.state()), 0.0)
                << (magnetic ? "MHD" : "fluid") << " after " << before << " steps";

            // Without it the first step starts cold: not the same iterate (what resume did).
            ModalStepper cold(context(), mC, model, {});
            cold.setState(resumed.state());
            cold.setForce(force);
            resumed.setState(cold.state());
            resumed.setWarmStart(whole.warmStart());
            runDevice(context(), resumed, mH, 1);
            runDevice(context(), cold, mH, 1);
            EXPECT_LT(resumed.status().iterations, cold.status().iterations);
        }
    }
    ModalStepper stepper(context(), mC, {}, {});
    const std::vector<Eigen::VectorXd> three(3, Eigen::VectorXd::Zero(kModes));
    EXPECT_THROW(stepper.setWarmStart(three), Error);
    EXPECT_THROW(stepper.setWarmStart({Eigen::VectorXd::Zero(kModes + 1)}), Error);
    EXPECT_THROW(stepper.setWarmStart({Eigen::VectorXd::Constant(kModes, NAN)}), Error);
    stepper.setIntegrator(Integrator::Trapezoidal);
    EXPECT_THROW(stepper.setWarmStart({Eigen::VectorXd::Zero(kModes)}), Error);
    stepper.setWarmStart({});  // starting cold is always allowed
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, StepsThatMissTheToleranceAreCounted) {
    DeviceStepSettings settings;
    settings.maxIterations = 1;
    settings.tolerance = 1e-12f;  // below float32 round-off: never met
    {
        ModalStepper stepper(context(), mC, {}, settings);
        stepper.setState(mV0);
        runDevice(context(), stepper, mH, 3);
        const device::DeviceStepStatus status = stepper.status();
        EXPECT_FALSE(status.converged);
        EXPECT_EQ(status.iterations, 1);
        EXPECT_EQ(status.unconvergedSteps, 3);
    }
}

TEST_P(ModalStepKernelTest, AnIterateThatIsNotFiniteNeverCountsAsConverged) {
    // |v| ~ 1e25: the pair sums reach ~1e26 and their products with v overflow float32, so every
    // iterate is inf or NaN. Such a step must keep its state and be counted (the host then takes
    // substeps), for both implicit rules, plain and accelerated.
    const Eigen::VectorXd huge = roundedToFloat(1e25 * mV0);
    for (const Integrator scheme : {Integrator::Midpoint, Integrator::Trapezoidal})
        for (const bool accelerated : {false, true}) {
            DeviceStepSettings settings;
            settings.scheme = scheme;
            settings.accelerated = accelerated;
            settings.maxIterations = 4;
            ModalStepper stepper(context(), mC, {}, settings);
            stepper.setState(huge);
            runDevice(context(), stepper, mH, 2);
            const device::DeviceStepStatus status = stepper.status();
            EXPECT_FALSE(status.converged) << int(scheme) << " " << accelerated;
            EXPECT_EQ(status.unconvergedSteps, 2) << int(scheme) << " " << accelerated;
            EXPECT_TRUE(stepper.state() == huge) << int(scheme) << " " << accelerated;
        }
    expectNoValidationMessages();
}

TEST_P(ModalStepKernelTest, RefusesStatesAndParametersOfTheWrongShape) {
    ModalStepper stepper(context(), mC, {});
    EXPECT_THROW(stepper.setState(Eigen::VectorXd::Zero(kModes + 1)), Error);
    EXPECT_THROW(stepper.setParameters(MhdParameters{}), Error);
    EXPECT_THROW(stepper.magneticField(), Error);
    FluidParameters held;
    held.held = {kModes};  // a held mode beyond the basis
    EXPECT_THROW(stepper.setParameters(held), Error);
    EXPECT_THROW(ModalStepper(context(), mC, held), Error);
    ModalStepper mhd(context(), mC, MhdParameters{});
    EXPECT_THROW(mhd.setState(Eigen::VectorXd::Zero(kModes)), Error);
    EXPECT_THROW(mhd.setIntegrator(Integrator::Linearized), Error);  // fluids only, as on the CPU
    EXPECT_THROW(ModalStepper(context(), mC, MhdParameters{}, {Integrator::Linearized}), Error);
    EXPECT_NO_THROW(mhd.setState(Eigen::VectorXd::Zero(2 * kModes)));
}

/// `steps` steps of MHD on the device and the CPU from [v; F] (random, F half the size), with
/// the Lorentz force, viscosity and magnetic diffusivity: the largest relative difference.
double mhdDifference(const vulkan::VulkanContext& context, const StructuralCoefficients& c,
                     Integrator scheme, int steps, const BasisCache* cache = nullptr) {
    const int n = c.size();
    const MhdParameters parameters{testing::shapedKappaSquared(n) / 100.0, 0.02, 0.03};
    const MhdSystem system(c, parameters);
    const Eigen::VectorXd x0 = roundedToFloat(
        system.state(testing::randomVector(n, 61), 0.5 * testing::randomVector(n, 62)));
    const double h = stepFor(c, x0.head(n), 0.02);
    ModalIntegrator cpu(system, {scheme});
    Eigen::VectorXd expected = x0;
    for (int s = 0; s < steps; ++s) cpu.step(expected, h);
    ModalStepper stepper(context, c, parameters, {scheme}, cache);
    stepper.setState(x0);
    stepper.setForce(Eigen::VectorXd::Zero(n));
    runDevice(context, stepper, h, steps);
    EXPECT_TRUE(stepper.status().converged);
    return relativeDifference(stepper.state(), expected);
}

TEST_P(ModalStepKernelTest, MhdStepsLikeTheCpuReferenceForEveryStorage) {
    const SparseCoefficients sparse =
        SparseCoefficients::fromDense(roundedDense(testing::randomDense(kModes, 63, 0.1)));
    const BasisCache cache = testing::withDeviceModes(testing::disk2d(), ModePrecision::Float32);
    const TensorFreeCoefficients free(cache.velocity.modes, cache.quadrature);
    for (const Integrator scheme :
         {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint, Integrator::Trapezoidal}) {
        const double dense = mhdDifference(context(), mC, scheme, 20);
        const double sparseError = mhdDifference(context(), sparse, scheme, 20);
        const double freeError = mhdDifference(context(), free, scheme, 20, &cache);
        std::cout << "MHD " << sceneKeyword(scheme) << ", 20 steps: relative error dense " << dense
                  << ", sparse " << sparseError << ", tensor-free " << freeError << "\n";
        EXPECT_LE(dense, 1e-5) << sceneKeyword(scheme);
        EXPECT_LE(sparseError, 1e-5) << sceneKeyword(scheme);
        EXPECT_LE(freeError, 1e-5) << sceneKeyword(scheme);
        expectNoValidationMessages();
    }
}

TEST_P(ModalStepKernelTest, MhdMidpointKeepsEnergyAndCrossHelicity) {
    const MhdSystem system(mC);
    const Eigen::VectorXd x0 =
        roundedToFloat(system.state(mV0, 0.5 * testing::randomVector(kModes, 64)));
    const double h = stepFor(mC, mV0, 0.3);
    ModalStepper stepper(context(), mC, MhdParameters{});
    stepper.setState(x0);
    const double e0 = energy(x0), h0 = crossHelicity(x0.head(kModes), x0.tail(kModes));
    double energyDrift = 0.0, helicityDrift = 0.0;
    for (int block = 0; block < 6; ++block) {
        runDevice(context(), stepper, h, 50);
        const Eigen::VectorXd x = stepper.state();
        energyDrift = std::max(energyDrift, std::abs(energy(x) - e0) / e0);
        helicityDrift = std::max(helicityDrift,
                                 std::abs(crossHelicity(x.head(kModes), x.tail(kModes)) - h0) / e0);
    }
    std::cout << "MHD midpoint, 300 steps: energy drift " << energyDrift
              << ", cross helicity drift " << helicityDrift << " (relative to the energy)\n";
    EXPECT_LE(energyDrift, 1e-5);
    EXPECT_LE(helicityDrift, 1e-5);
    EXPECT_EQ(stepper.status().unconvergedSteps, 0);
}

TEST(ModalStepSplit, SplitStagedCoefficientsStepLikeWholeMappedOnes) {
    vulkan::VulkanContextOptions options;
    options.validation = true;
    options.forceStaging = true;  // device-local buffers, as on a discrete GPU
    options.storageBufferLimit =
        20'000;  // 40 modes: 780 pairs of 160 bytes, 13 chunks of one 64-pair tile
    std::unique_ptr<vulkan::VulkanContext> split;
    ASSERT_NO_THROW(split = std::make_unique<vulkan::VulkanContext>(options));
    const vulkan::VulkanContext whole{vulkan::VulkanContextOptions{}};
    const DenseCoefficients c = roundedDense(testing::randomDense(kModes, 31));
    const Eigen::VectorXd v = testing::randomVector(kModes, 32);
    const double h = stepFor(c, v, 0.2);
    {
        ModalStepper a(*split, c, {}), b(whole, c, {});
        EXPECT_EQ(a.coefficients().chunkCount(), 13u);
        a.setState(v);
        b.setState(v);
        runDevice(*split, a, h, 10);
        runDevice(whole, b, h, 10);
        EXPECT_LE(relativeDifference(a.state(), b.state()), 1e-6);
    }
    EXPECT_EQ(split->validationMessageCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(PlainAndValidated, ModalStepKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
