/// @file ModalStepKernelTest.cpp
/// ModalStepper (the modal step on the device, float32) against the double-precision CPU
/// reference ModalIntegrator: single steps of every scheme with forces, viscosity and LANS-α;
/// trajectories; midpoint energy conservation; convergence reporting; split coefficients.

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/core/Error.h"
#include "engine/device/ModalStepper.h"
#include "engine/vulkan/CommandSequence.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using testing::roundedDense;
using testing::roundedToFloat;

using vulkan::CommandSequence;
using device::DeviceStepSettings;
using device::ModalStepper;

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
};

TEST_P(ModalStepKernelTest, OneStepOfEverySchemeEqualsTheCpuReference) {
    FluidParameters viscousLans;
    viscousLans.kappaSquared = testing::shapedKappaSquared(kModes) / 100.0;
    viscousLans.viscosity = 0.05;
    viscousLans.alpha = 0.1;
    const Eigen::VectorXd force = roundedToFloat(0.3 * testing::randomVector(kModes, 13));
    for (const FluidParameters& parameters : {FluidParameters{}, viscousLans}) {
        const FluidSystem system(mC, parameters);
        for (const Integrator scheme :
             {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint}) {
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

TEST_P(ModalStepKernelTest, SparseCoefficientsStepLikeDenseOnes) {
    const DenseCoefficients dense = roundedDense(testing::randomDense(kModes, 21, 0.1));
    const SparseCoefficients sparse = SparseCoefficients::fromDense(dense);
    const double h = stepFor(dense, mV0, 0.1);
    {
        ModalStepper fromDense(context(), dense, {}), fromSparse(context(), sparse, {});
        for (ModalStepper* stepper : {&fromDense, &fromSparse}) {
            stepper->setState(mV0);
            runDevice(context(), *stepper, h, 5);
        }
        EXPECT_LE(relativeDifference(fromSparse.state(), fromDense.state()), 1e-6);
    }
}

TEST_P(ModalStepKernelTest, TrajectoriesStayWithin1e4OfTheDoubleReference) {
    const FluidSystem system(mC);
    for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint}) {
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

TEST_P(ModalStepKernelTest, MidpointConservesEnergyOver1000Steps) {
    const double h = stepFor(mC, mV0, 0.3);  // the CPU tests' large step
    {
        ModalStepper stepper(context(), mC, {});
        stepper.setState(mV0);
        const double e0 = energy(mV0);
        double drift = 0.0;
        int maxIterations = 0;
        for (int block = 0; block < 10; ++block) {
            runDevice(context(), stepper, h, 100);
            drift = std::max(drift, std::abs(energy(stepper.state()) - e0) / e0);
            maxIterations = std::max(maxIterations, stepper.status().iterations);
        }
        std::cout << "midpoint, 1000 steps of h|R|/|v| = 0.3: energy drift " << drift
                  << ", last step " << stepper.status().iterations << " iterations\n";
        EXPECT_LE(drift, 1e-5);
        EXPECT_EQ(stepper.status().unconvergedSteps, 0);
    }
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

TEST_P(ModalStepKernelTest, RefusesWhatOnlyTheCpuRuns) {
    try {
        ModalStepper stepper(context(), mC, {}, {Integrator::Trapezoidal});
        FAIL() << "trapezoidal accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--device cpu"), std::string::npos) << e.what();
    }
    ModalStepper stepper(context(), mC, {});
    EXPECT_THROW(stepper.setState(Eigen::VectorXd::Zero(kModes + 1)), Error);
}

TEST(ModalStepSplit, SplitStagedCoefficientsStepLikeWholeMappedOnes) {
    vulkan::VulkanContextOptions options;
    options.validation = true;
    options.forceStaging = true;          // device-local buffers, as on a discrete GPU
    options.storageBufferLimit = 20'000;  // 40 modes: 780 pairs of 160 bytes, 13 chunks of one 64-pair tile
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
