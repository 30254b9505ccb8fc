/// Surface scenes on the device (engine/device/SurfaceSimulation) against the CPU reference
/// (engine/surface/SurfaceSimulation), with and without the validation layer: every integrator's
/// velocity, the dye it carries and the stirring splats' force agree to float32's precision; the
/// device's dye step keeps the dye's variance (its Cayley step), its sources raise the mean at
/// their rate, a step far past the dye's explicit limit still solves; and a run resumed from a
/// checkpoint's state and carry gives the uninterrupted run's states bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/SceneKeywords.h"
#include "engine/device/SurfaceDye.h"
#include "engine/device/SurfaceForce.h"
#include "engine/device/SurfaceSimulation.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/simulation/SurfaceSources.h"
#include "engine/surface/SurfaceDye.h"
#include "engine/surface/SurfaceForce.h"
#include "engine/surface/SurfaceSimulation.h"
#include "engine/vulkan/CommandSequence.h"
#include "tests/support/SurfaceRuns.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow::testing {
namespace {

/// The unit sphere (642 vertices), 20 velocity modes, 40 scalar modes, a dye source at the
/// north pole for the first 0.3 s, a random flow of energy 0.5; once per process.
const RunInputs& sphereRun() {
    static const RunInputs run = [] {
        RunInputs prepared = icosphereRun({20, 40, 0.002, 0.3});
        prepared.initialVelocity = randomVelocity(prepared.modeCount(), {0, -1, 0.5, 7});
        return prepared;
    }();
    return run;
}

double relativeGap(const Eigen::VectorXd& device, const Eigen::VectorXd& reference) {
    return (device - reference).norm() / reference.norm();
}

/// A dye state with every mode set, of norm 1 and mean 0.2.
Eigen::VectorXd spreadDye() {
    const int m = int(sphereRun().cache.scalar.modes.cols());
    Eigen::VectorXd dye(m + 1);
    dye[0] = 0.2;
    for (int i = 0; i < m; ++i) dye[i + 1] = std::cos(1.7 * i + 0.3);
    dye.tail(m).normalize();
    return dye;
}

class SurfaceDevice : public VulkanTest {};

TEST_P(SurfaceDevice, EveryIntegratorFollowsTheCpuReference) {
    const RunInputs& run = sphereRun();
    for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                    Integrator::Trapezoidal, Integrator::Linearized}) {
        SimulationSettings settings = run.settings;
        settings.integrator = scheme;
        SurfaceSimulation cpu(run.cache, *run.coefficients, settings, run.initialVelocity);
        device::SurfaceSimulation gpu(context(), run.cache, *run.coefficients, settings,
                                      run.initialVelocity);
        // 0.5 s: the source emits for the first 0.3 s, then the flow carries the dye alone.
        const FrameStats stats = gpu.advanceSteps(25);
        cpu.advanceSteps(25);
        EXPECT_EQ(stats.steps, 25);
        EXPECT_EQ(stats.unconvergedSteps, 0) << sceneKeyword(scheme);
        EXPECT_DOUBLE_EQ(gpu.time(), cpu.time());
        EXPECT_LT(relativeGap(gpu.velocity(), cpu.velocity()), 1e-5) << sceneKeyword(scheme);
        EXPECT_LT(relativeGap(gpu.dye(), cpu.dye()), 1e-5) << sceneKeyword(scheme);
        EXPECT_GT(cpu.dye()[0], 0.0) << "the source raised the mean";
        EXPECT_TRUE(gpu.dyeStatus().converged) << sceneKeyword(scheme);
    }
}

TEST_P(SurfaceDevice, DyeKeepsItsVarianceAndSourcesRaiseItsMean) {
    const RunInputs& run = sphereRun();
    // Carried alone (the source has stopped): |f| and the mean stay.
    device::SurfaceSimulation carried(context(), run.cache, *run.coefficients, run.settings,
                                      run.initialVelocity);
    const Eigen::VectorXd dye = spreadDye();
    carried.restore(1.0, run.initialVelocity, dye);
    carried.advanceSteps(100);
    const Eigen::VectorXd after = carried.dye();
    const Eigen::Index m = dye.size() - 1;
    EXPECT_NEAR(after.tail(m).norm(), 1.0, 1e-5);
    EXPECT_GT((after.tail(m) - dye.tail(m)).norm(), 0.1) << "the flow moved the dye";
    EXPECT_FLOAT_EQ(float(after[0]), 0.2f);
    // From t = 0 the source adds its rate times its share of the area to the mean each step.
    device::SurfaceSimulation fed(context(), run.cache, *run.coefficients, run.settings,
                                  run.initialVelocity);
    fed.advanceSteps(10);
    const double share = SurfaceSources(run.cache, run.settings.emitters).rateAt(0.0)[0];
    EXPECT_GT(share, 0.0);
    EXPECT_NEAR(fed.dye()[0], 10 * run.settings.dt * share, 1e-6);
}

TEST_P(SurfaceDevice, DyeStepFarPastTheExplicitLimitSolves) {
    // A fast flow and a long step: h/2 |K| ≫ 1, where a plain fixed-point iteration diverges;
    // the dye kernels alone, the velocity going from v0 to v1 over the step.
    const RunInputs& run = sphereRun();
    const double h = 0.5;
    const Eigen::VectorXd v0 = 20.0 * run.initialVelocity;
    const Eigen::VectorXd v1 = 20.0 * randomVelocity(run.modeCount(), {0, -1, 0.5, 8});
    const auto onDevice = [&](const Eigen::VectorXd& v, const char* name) {
        const std::vector<float> values(v.begin(), v.end());
        return vulkan::DeviceBuffer::fromValues<float>(context(), values, name);
    };
    const vulkan::DeviceBuffer before = onDevice(v0, "v0"), after = onDevice(v1, "v1");
    device::SurfaceDye gpu(context(), run.cache, run.settings.emitters);
    SurfaceDye cpu(run.cache, run.settings.emitters);
    gpu.setState(spreadDye());
    cpu.setState(spreadDye());
    vulkan::CommandSequence sequence(context());
    gpu.setRate(0.1);
    gpu.recordStep(sequence, before, after, h);
    sequence.submitAndWait();
    cpu.step(v0, v1, 0.1, h);
    const device::SurfaceDyeStatus status = gpu.status();
    EXPECT_TRUE(status.converged) << status.iterations << " iterations, residual "
                                  << status.residual;
    EXPECT_GT(status.iterations, 5);
    EXPECT_LT(relativeGap(gpu.state(), cpu.state()), 1e-4);
    EXPECT_GT((cpu.state() - spreadDye()).norm(), 0.5) << "a step that moves the dye";
}

TEST_P(SurfaceDevice, SplatForceFollowsTheCpuReference) {
    const RunInputs& run = sphereRun();
    // East on the equator, and a push along the normal at the south pole (its tangent part
    // only counts), together.
    const std::vector<ForceSplat> splats{{{1.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, 0.3},
                                         {{0.0, 0.0, -1.0}, {0.5, 0.0, -1.0}, 0.5}};
    const Eigen::VectorXd reference = SurfaceForce(run.cache).project(splats);
    device::SurfaceForce force(context(), run.cache);
    vulkan::DeviceBuffer modal(context(), std::size_t(run.modeCount()) * sizeof(float), "f");
    vulkan::CommandSequence sequence(context());
    force.record(sequence, splats, modal);
    sequence.submitAndWait();
    std::vector<float> values(std::size_t(run.modeCount()));
    modal.download<float>(values);
    const Eigen::VectorXd onDevice =
        Eigen::Map<const Eigen::VectorXf>(values.data(), run.modeCount()).cast<double>();
    EXPECT_GT(reference.norm(), 0.1);
    EXPECT_LT(relativeGap(onDevice, reference), 1e-5);
    // No splats: no force.
    force.record(sequence, {}, modal);
    sequence.submitAndWait();
    modal.download<float>(values);
    for (const float f : values) EXPECT_EQ(f, 0.0f);
    // What neither backend takes.
    const std::vector<ForceSplat> many(maxForceSplats + 1, splats[0]);
    const ForceSplat flat{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.0};
    EXPECT_THROW(force.record(sequence, many, modal), Error);
    EXPECT_THROW(SurfaceForce(run.cache).project(many), Error);
    EXPECT_THROW(force.record(sequence, std::span(&flat, 1), modal), Error);
    // Stirred flows: the force held over the steps moves both backends' fluids alike.
    SurfaceSimulation cpu(run.cache, *run.coefficients, run.settings, run.initialVelocity);
    device::SurfaceSimulation gpu(context(), run.cache, *run.coefficients, run.settings,
                                  run.initialVelocity);
    cpu.setSplats(splats);
    gpu.setSplats(splats);
    cpu.advanceSteps(10);
    gpu.advanceSteps(10);
    SurfaceSimulation still(run.cache, *run.coefficients, run.settings, run.initialVelocity);
    still.advanceSteps(10);
    EXPECT_GT((cpu.velocity() - still.velocity()).norm(), 0.05) << "the splats stirred";
    EXPECT_LT(relativeGap(gpu.velocity(), cpu.velocity()), 1e-5);
}

TEST_P(SurfaceDevice, ResumedRunsEqualUninterruptedOnes) {
    const RunInputs& run = sphereRun();
    for (const Integrator scheme : {Integrator::Midpoint, Integrator::Linearized}) {
        SimulationSettings settings = run.settings;
        settings.integrator = scheme;
        device::SurfaceSimulation whole(context(), run.cache, *run.coefficients, settings,
                                        run.initialVelocity);
        whole.advanceSteps(8);  // the source still emits across the checkpoint
        const double time = whole.time();
        const Eigen::VectorXd velocity = whole.velocity(), dye = whole.dye();
        const StepCarry carry = whole.carry();
        whole.advanceSteps(12);

        device::SurfaceSimulation resumed(context(), run.cache, *run.coefficients, settings,
                                          Eigen::VectorXd::Zero(run.modeCount()));
        resumed.restore(time, velocity, dye);
        resumed.setCarry(carry);
        resumed.advanceSteps(12);
        EXPECT_EQ(resumed.time(), whole.time());
        EXPECT_EQ(resumed.velocity(), whole.velocity()) << sceneKeyword(scheme);
        EXPECT_EQ(resumed.dye(), whole.dye()) << sceneKeyword(scheme);
    }
}

TEST_P(SurfaceDevice, StepsRecordedOnceGiveTheTrajectoriesOfStepsRecordedEachTime) {
    const RunInputs& run = sphereRun();
    const auto trajectory = [&](device::StepRecording recording) {
        device::SurfaceSimulation gpu(context(), run.cache, *run.coefficients, run.settings,
                                      run.initialVelocity, recording);
        std::vector<Eigen::VectorXd> states;
        const auto record = [&] {
            states.push_back(gpu.velocity());
            states.push_back(gpu.dye());
        };
        gpu.advanceSteps(6);  // the source still emits: its rate changes from step to step
        record();
        gpu.setIntegrator(Integrator::Rk4);  // what a step records changes
        gpu.advanceSteps(5);
        record();
        gpu.setViscosity(0.01);
        gpu.setIntegrator(Integrator::Linearized);
        gpu.advanceSteps(5);
        record();
        gpu.setSplats(std::vector<ForceSplat>{{{1.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, 0.3}});
        gpu.advanceSteps(5);
        record();
        return states;
    };
    EXPECT_EQ(trajectory(device::StepRecording::Once),
              trajectory(device::StepRecording::EveryStep));
}

TEST_P(SurfaceDevice, BadStatesAndSchedulesAreRefused) {
    const RunInputs& run = sphereRun();
    device::SurfaceSimulation gpu(context(), run.cache, *run.coefficients, run.settings,
                                  run.initialVelocity);
    EXPECT_THROW(gpu.restore(0.0, run.initialVelocity, Eigen::VectorXd::Zero(3)), Error);
    EXPECT_THROW(gpu.restore(0.0, Eigen::VectorXd::Zero(3), spreadDye()), Error);
    StepCarry carry;
    carry.substeps = 3;  // not a power of two
    EXPECT_THROW(gpu.setCarry(carry), Error);
    // A diverging state is caught after its step, as on the CPU.
    Eigen::VectorXd huge = run.initialVelocity;
    huge[0] = std::numeric_limits<double>::quiet_NaN();
    gpu.restore(0.0, huge, spreadDye());
    EXPECT_THROW(gpu.advanceSteps(1), ModalStateDiverged);
}

INSTANTIATE_TEST_SUITE_P(Validation, SurfaceDevice, ::testing::Bool());

TEST(SurfaceDeviceMemory, StagedBuffersGiveTheSameRun) {
    // Device-local buffers reached through staging copies, as on a discrete GPU.
    vulkan::VulkanContextOptions options;
    options.forceStaging = true;
    options.validation = true;
    const vulkan::VulkanContext staged(options);
    const std::unique_ptr<vulkan::VulkanContext> mapped = makeVulkanContext(false);
    ASSERT_NE(mapped, nullptr);
    const RunInputs& run = sphereRun();
    {
        device::SurfaceSimulation a(staged, run.cache, *run.coefficients, run.settings,
                                    run.initialVelocity);
        device::SurfaceSimulation b(*mapped, run.cache, *run.coefficients, run.settings,
                                    run.initialVelocity);
        const std::vector<ForceSplat> splat{{{1.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, 0.3}};
        a.setSplats(splat);
        b.setSplats(splat);
        a.advanceSteps(6);
        b.advanceSteps(6);
        EXPECT_EQ(a.velocity(), b.velocity());
        EXPECT_EQ(a.dye(), b.dye());
    }
    EXPECT_EQ(staged.validationMessageCount(), 0u);
}

TEST(SurfaceDeviceMemory, ADyeLargerThanTheDeviceHoldsIsRefusedNamingTheKey) {
    // 40 scalar modes: 780 pairs (195 texels) by 20 velocity modes, 62.4 kB of coefficients.
    vulkan::VulkanContextOptions options;
    options.storageBufferLimit = 10'000;
    const vulkan::VulkanContext small(options);
    const RunInputs& run = sphereRun();
    try {
        const device::SurfaceDye dye(small, run.cache, run.settings.emitters);
        ADD_FAILURE() << "62.4 kB of advection coefficients under a 10 kB limit were accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("40 scalar modes by 20 velocity modes (62400 bytes"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("use fewer scalar_modes or --device cpu"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace modeflow::testing
