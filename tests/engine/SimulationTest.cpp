/// @file SimulationTest.cpp
/// The whole runtime chain on the device (Simulation) against the CPU reference chain
/// (reference::Simulation) on a real basis: a disk with a hot smoke source, buoyancy and a swirl.

#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/SceneKeywords.h"
#include "engine/device/Simulation.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/dynamics/TensorFreeCoefficients.h"
#include "engine/reference/Simulation.h"
#include "engine/simulation/Checkpoint.h"
#include "engine/simulation/ParticleEmission.h"
#include "engine/simulation/ParticleMotion.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

/// A unit disk at 32² with 20 modes (or a unit ball at 12³ with 10), a hot source low in it,
/// buoyancy, smoke at 2× the basis resolution.
SceneSpec hotScene(int dim) {
    SceneSpec scene = testing::unitBallScene(dim, dim == 2 ? 32 : 12, dim == 2 ? 20 : 10, 0);
    scene.name = "hot";
    scene.simulation.dt = 0.02;
    scene.output.stepsPerFrame = 5;
    scene.smoke.buoyancy = 2.0;
    scene.smoke.resolutionScale = 2;
    SourceSpec source;
    source.shape = testing::ball(dim == 2 ? Vec3{0.0, -0.55, 0.0} : Vec3{0.0, 0.0, -0.55},
                                 dim == 2 ? 0.2 : 0.3);
    source.density = 2.0;
    source.temperature = 1.0;
    scene.sources = {source};
    return scene;
}

const RunInputs& hotDisk() {
    static const RunInputs disk = testing::sharedRun(hotScene(2));
    return disk;
}

const RunInputs& hotBall() {
    static const RunInputs ball = testing::sharedRun(hotScene(3));
    return ball;
}

double maxAbs(const std::vector<double>& values) {
    double m = 0.0;
    for (double v : values) m = std::max(m, std::abs(v));
    return m;
}

double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
    return m;
}

class SimulationTest : public testing::VulkanTest {};

/// How far a device run lies from its CPU reference: relative max differences of the modes, the
/// grid velocity and the density; the max difference of the particles' positions among those
/// still in the run, and how many have left it (after checking both agree on which).
struct BackendDifferences {
    double modes = 0.0, faceVelocity = 0.0, density = 0.0, particles = 0.0;
    int left = 0;
};

BackendDifferences differences(const Simulator& device, const Simulator& cpu) {
    BackendDifferences d;
    const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
    d.modes = (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
    d.faceVelocity =
        maxDifference(device.faceVelocity(), cpu.faceVelocity()) / maxAbs(cpu.faceVelocity());
    const std::vector<double> density = cpu.smoke().density;
    d.density = maxDifference(device.smoke().density, density) / maxAbs(density);
    const Particles onDevice = device.particles(), tracked = cpu.particles();
    EXPECT_EQ(onDevice.size(), tracked.size());
    for (std::size_t i = 0; i < std::min(onDevice.size(), tracked.size()); ++i) {
        const bool gone = particleLeft(&tracked.position[3 * i], &tracked.velocity[3 * i]);
        EXPECT_EQ(particleLeft(&onDevice.position[3 * i], &onDevice.velocity[3 * i]), gone)
            << "particle " << i;
        d.left += gone;
        if (gone) continue;
        for (std::size_t a = 0; a < 3; ++a)
            d.particles = std::max(
                d.particles, std::abs(onDevice.position[3 * i + a] - tracked.position[3 * i + a]));
    }
    return d;
}

/// The largest density in the smoke cells `solid` covers now.
double maxInside(const Simulator& run, const MovingObstacle& solid) {
    const MacGrid& grid = run.smokeGrid();
    const std::vector<double> density = run.smoke().density;
    const ObstaclePose pose = solid.poseAt(run.time());
    double most = 0.0;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x)
                if (solid.covers(testing::cellCentre(grid, x, y, z), pose, grid))
                    most = std::max(most, std::abs(density[std::size_t(grid.cellIndex(x, y, z))]));
    return most;
}

TEST_P(SimulationTest, DeviceRunFollowsTheCpuReference) {
    for (const auto& [disk, scheme] : {std::pair{&hotDisk(), AdvectionScheme::SemiLagrangian},
                                       std::pair{&hotDisk(), AdvectionScheme::MacCormack},
                                       std::pair{&hotBall(), AdvectionScheme::MacCormack}}) {
        SimulationSettings settings = disk->settings;
        settings.advection = scheme;
        {
            device::Simulation device(context(), disk->cache, *disk->coefficients, settings,
                                      disk->smokeMask, true);
            reference::Simulation cpu(disk->cache, *disk->coefficients, settings, disk->smokeMask);
            RandomVelocitySpec swirl;
            swirl.energy = 0.05;
            const Eigen::VectorXd v0 = randomVelocity(disk->coefficients->size(), swirl);
            device.setVelocity(v0);
            cpu.setVelocity(v0);
            FrameStats stats;
            for (int frame = 0; frame < 4; ++frame) {
                stats = device.advanceFrame();
                cpu.advanceFrame();
            }
            EXPECT_EQ(stats.steps, 5);
            EXPECT_EQ(stats.unconvergedSteps, 0);
            EXPECT_NEAR(device.time(), 20 * 0.02, 1e-12);

            const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
            const double velocityError =
                (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
            const SmokeFields smoke = device.smoke(), expectedSmoke = cpu.smoke();
            const double densityError =
                maxDifference(smoke.density, expectedSmoke.density) / maxAbs(expectedSmoke.density);
            const double temperatureError =
                maxDifference(smoke.temperature, expectedSmoke.temperature) /
                maxAbs(expectedSmoke.temperature);
            const double faceError = maxDifference(device.faceVelocity(), cpu.faceVelocity()) /
                                     maxAbs(cpu.faceVelocity());
            std::cout << disk->scene.grid.dim << "D, "
                      << (scheme == AdvectionScheme::MacCormack ? "MacCormack" : "semi-Lagrangian")
                      << ", 20 steps: relative max differences: modes " << velocityError
                      << ", grid velocity " << faceError << ", density " << densityError
                      << ", temperature " << temperatureError << "; device ms per frame: forces "
                      << stats.forcesMs << ", modal " << stats.modalMs << ", reconstruction "
                      << stats.reconstructionMs << ", advection " << stats.advectionMs << "\n";
            EXPECT_LE(velocityError, 1e-4);
            EXPECT_LE(faceError, 1e-4);
            EXPECT_LE(densityError, 1e-4);
            EXPECT_LE(temperatureError, 1e-4);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SimulationTest, TensorFreeRunFollowsTheCpuReference) {
    const RunInputs& ball = hotBall();
    const TensorFreeCoefficients coefficients(ball.cache.velocity.modes, ball.cache.quadrature);
    {
        device::Simulation device(context(), ball.cache, coefficients, ball.settings,
                                  ball.smokeMask);
        reference::Simulation cpu(ball.cache, coefficients, ball.settings, ball.smokeMask);
        RandomVelocitySpec swirl;
        swirl.energy = 0.05;
        const Eigen::VectorXd v0 = randomVelocity(coefficients.size(), swirl);
        device.setVelocity(v0);
        cpu.setVelocity(v0);
        for (int frame = 0; frame < 4; ++frame) {
            device.advanceFrame();
            cpu.advanceFrame();
        }
        const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
        const double error =
            (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
        std::cout << "3D tensor-free, 20 steps: relative max difference of the modes " << error
                  << "\n";
        EXPECT_LE(error, 1e-4);
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, MhdRunFollowsTheCpuReference) {
    SceneSpec scene = hotScene(2);
    scene.simulation.mhd = true;
    scene.simulation.magneticDiffusivity = 1e-3;
    const RunInputs disk = testing::sharedRun(scene);
    {
        device::Simulation device(context(), disk.cache, *disk.coefficients, disk.settings,
                                  disk.smokeMask);
        reference::Simulation cpu(disk.cache, *disk.coefficients, disk.settings, disk.smokeMask);
        RandomVelocitySpec swirl;
        swirl.energy = 0.05;
        const Eigen::VectorXd v0 = randomVelocity(disk.coefficients->size(), swirl);
        swirl.seed += 1;
        const Eigen::VectorXd f0 = randomVelocity(disk.coefficients->size(), swirl);
        for (Simulator* s : std::initializer_list<Simulator*>{&device, &cpu}) {
            s->setVelocity(v0);
            s->setMagneticField(f0);
        }
        for (int frame = 0; frame < 4; ++frame) {
            device.advanceFrame();
            cpu.advanceFrame();
        }
        const auto relative = [](const Eigen::VectorXd& got, const Eigen::VectorXd& want) {
            return (got - want).lpNorm<Eigen::Infinity>() / want.lpNorm<Eigen::Infinity>();
        };
        const double velocityError = relative(device.velocity(), cpu.velocity());
        const double fieldError = relative(device.magneticField(), cpu.magneticField());
        const double faceError =
            maxDifference(device.faceMagneticField(), cpu.faceMagneticField()) /
            maxAbs(cpu.faceMagneticField());
        std::cout << "2D MHD, 20 steps: relative max differences: velocity " << velocityError
                  << ", field " << fieldError << ", field on the faces " << faceError << "\n";
        EXPECT_GT(relative(cpu.magneticField(), f0), 1e-3) << "the field hardly moved: a weak test";
        EXPECT_LE(velocityError, 1e-4);
        EXPECT_LE(fieldError, 1e-4);
        EXPECT_LE(faceError, 1e-4);
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, TimingSamplesOnlyTheStepsAskedFor) {
    const auto& disk = hotDisk();
    const SimulationSettings settings = disk.settings;
    device::Simulation device(context(), disk.cache, *disk.coefficients, settings, disk.smokeMask,
                              true);
    if (context().timestampValidBits() == 0) GTEST_SKIP() << "the queue writes no timestamps";
    const FrameStats timed = device.advanceSteps(2);
    EXPECT_EQ(timed.timedSteps, 2);
    EXPECT_GT(timed.modalMs, 0.0);
    // The same time by kernel: every dispatch named, the stages' sum.
    double byKernel = 0.0;
    for (const auto& [kernel, ms] : timed.kernelMs) byKernel += ms;
    EXPECT_NEAR(byKernel,
                timed.forcesMs + timed.modalMs + timed.reconstructionMs + timed.obstaclesMs +
                    timed.advectionMs + timed.particlesMs,
                1e-9 * byKernel);
    EXPECT_EQ(timed.kernelMs.count(""), 0u);
    EXPECT_EQ(timed.kernelMs.count("modal_update"), 0u);
    EXPECT_TRUE(std::any_of(timed.kernelMs.begin(), timed.kernelMs.end(), [](const auto& k) {
        return k.first.rfind("modal_update(", 0) == 0;
    })) << "a variant is named with its specialization constants";
    device.setTiming(false);
    const FrameStats untimed = device.advanceSteps(3);
    EXPECT_EQ(untimed.steps, 3);
    EXPECT_EQ(untimed.timedSteps, 0);
    EXPECT_EQ(untimed.forcesMs + untimed.modalMs + untimed.reconstructionMs + untimed.advectionMs,
              0.0);
    EXPECT_TRUE(untimed.kernelMs.empty());
    device.setTiming(true);
    EXPECT_EQ(device.advanceSteps(1).timedSteps, 1);
    expectNoValidationMessages();
}

TEST_P(SimulationTest, HotSmokeRisesAndStaysInsideTheDomain) {
    const RunInputs& disk = hotDisk();
    const SimulationSettings settings = disk.settings;
    {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask);
        device.advanceFrame();
        const double start = testing::centroid(device.smokeGrid(), device.smoke().density)[1];
        for (int frame = 0; frame < 8; ++frame) device.advanceFrame();
        const SmokeFields smoke = device.smoke();
        const double end = testing::centroid(device.smokeGrid(), smoke.density)[1];
        std::cout << "smoke centroid height " << start << " -> " << end << " over 40 steps\n";
        EXPECT_GT(end, start + 0.02) << "buoyancy must lift the hot smoke";
        EXPECT_GT(device.velocity().norm(), 0.0);
        for (std::size_t c = 0; c < disk.smokeMask.size(); ++c)
            if (!disk.smokeMask[c]) {
                ASSERT_EQ(smoke.density[c], 0.0) << "density outside the domain at cell " << c;
                ASSERT_EQ(smoke.temperature[c], 0.0)
                    << "temperature outside the domain at cell " << c;
            }
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, SplatsStirTheFluidOnlyWhileSet) {
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    settings.buoyancy = 0.0;
    settings.emitters.clear();
    {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask);
        device.advanceFrame();
        EXPECT_EQ(device.velocity().norm(), 0.0) << "no force, no motion";
        const ForceSplat push{{0.0, 0.0, 0.0}, {5.0, 0.0, 0.0}, 0.3};
        device.setSplats(std::span(&push, 1));
        device.advanceFrame();
        const Eigen::VectorXd stirred = device.velocity();
        EXPECT_GT(stirred.norm(), 0.0);
        // The grid velocity at the centre points along the push.
        const MacGrid grid = MacGrid::fromSpec(disk.cache.grid);
        EXPECT_GT(device.faceVelocity()[std::size_t(grid.faceIndex(0, 16, 16, 0))], 0.0);
        device.setSplats({});
        device.advanceFrame();  // inviscid, unforced: the energy stays
        EXPECT_NEAR(device.velocity().squaredNorm() / stirred.squaredNorm(), 1.0, 1e-4);
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, MovingObstaclesMatchTheCpuReference) {
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    ObstacleSpec paddle;
    paddle.shape = ObstacleShape::Capsule;
    paddle.radius = 0.1;
    paddle.axis = {0.0, 0.25, 0.0};
    paddle.path = {{0.0, {-0.5, 0.0, 0.0}}, {1.0, {0.5, 0.0, 0.0}}};
    settings.obstacles = {MovingObstacle{paddle}};
    {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask, true);
        reference::Simulation cpu(disk.cache, *disk.coefficients, settings, disk.smokeMask);
        FrameStats stats;
        for (int frame = 0; frame < 2; ++frame) {
            stats = device.advanceFrame();
            cpu.advanceFrame();
        }
        const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
        ASSERT_GT(expected.norm(), 0.0) << "the paddle must stir the fluid";
        const double error =
            (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
        std::cout << "moving capsule, 10 steps: modes relative difference " << error
                  << ", obstacle stage " << stats.obstaclesMs << " ms per frame\n";
        EXPECT_LE(error, 1e-4);
        EXPECT_LE(maxDifference(device.smoke().density, cpu.smoke().density),
                  1e-4 * maxAbs(cpu.smoke().density));
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, AFireWithASolidMatchesTheCpuReference) {
    // The hot disk's source also feeds fuel that burns above 0.05, and a capsule sweeps into
    // the source: fuel and flame are advected, pushed out of the solid and burnt as the CPU
    // reference does them, both schemes.
    const RunInputs& disk = hotDisk();
    for (const AdvectionScheme scheme :
         {AdvectionScheme::SemiLagrangian, AdvectionScheme::MacCormack}) {
        SimulationSettings settings = disk.settings;
        settings.advection = scheme;
        settings.emitters[0].fuelRate = 4.0;
        FireSpec fire;
        // Far from the temperatures the steps reach (0.02 a step at the source): no cell sits
        // at the ignition, where float32 and double would decide differently.
        fire.ignition = 0.05;
        fire.burnRate = 3.0;
        settings.fire = fire;
        ObstacleSpec paddle;
        paddle.shape = ObstacleShape::Capsule;
        paddle.radius = 0.1;
        paddle.axis = {0.0, 0.15, 0.0};
        paddle.path = {{0.0, {-0.5, -0.55, 0.0}}, {1.0, {0.5, -0.55, 0.0}}};
        settings.obstacles = {MovingObstacle{paddle}};
        {
            device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                      disk.smokeMask, true);
            reference::Simulation cpu(disk.cache, *disk.coefficients, settings, disk.smokeMask);
            for (int frame = 0; frame < 3; ++frame) {
                device.advanceFrame();
                cpu.advanceFrame();
            }
            const SmokeFields smoke = device.smoke(), expected = cpu.smoke();
            ASSERT_EQ(smoke.fuel.size(), expected.fuel.size());
            ASSERT_EQ(smoke.flame.size(), expected.flame.size());
            ASSERT_GT(maxAbs(expected.flame), 0.1) << "the fuel burns";
            const auto relative = [](const std::vector<double>& a, const std::vector<double>& b) {
                return maxDifference(a, b) / maxAbs(b);
            };
            std::cout << "fire and capsule, " << testing::schemeName(scheme)
                      << ", 15 steps: relative max differences: fuel "
                      << relative(smoke.fuel, expected.fuel) << ", flame "
                      << relative(smoke.flame, expected.flame) << ", temperature "
                      << relative(smoke.temperature, expected.temperature) << "\n";
            EXPECT_LE(relative(smoke.fuel, expected.fuel), 1e-4);
            EXPECT_LE(relative(smoke.flame, expected.flame), 1e-4);
            EXPECT_LE(relative(smoke.temperature, expected.temperature), 1e-4);
            EXPECT_LE(relative(smoke.density, expected.density), 1e-4);
            EXPECT_LE((device.velocity() - cpu.velocity()).lpNorm<Eigen::Infinity>() /
                          cpu.velocity().lpNorm<Eigen::Infinity>(),
                      1e-4);

            // A checkpoint's smoke with or without fuel belongs to runs with or without fire.
            SmokeFields noFuel = expected;
            noFuel.fuel.clear();
            noFuel.flame.clear();
            EXPECT_THROW(device.restore(0.0, cpu.velocity(), noFuel), Error);
            device.restore(cpu.time(), cpu.velocity(), expected);
            EXPECT_LE(maxDifference(device.smoke().flame, expected.flame),
                      1e-6 * maxAbs(expected.flame));
        }
        expectNoValidationMessages();
    }
}

/// A box source of smoke blowing `velocity` until just before `end`, moved along `path`.
SmokeEmitter boxJet(const Vec3& min, const Vec3& max, const Vec3& velocity, double end,
                    std::vector<std::pair<double, Vec3>> path) {
    SmokeEmitter jet;
    jet.shape = EmitterShape::Box;
    jet.min = min;
    jet.max = max;
    jet.densityRate = 1.0;
    jet.end = end - 1e-9;
    jet.velocity = velocity;
    jet.path = std::move(path);
    return jet;
}

TEST_P(SimulationTest, ASourceWithAVelocityDrivesTheAirAndMatchesTheCpuReference) {
    // A jet: a box source blowing along +x at 1.5 in still air for the first 0.1 s (5 steps), then
    // off, sliding along +x on key frames as it blows. While on, the air inside moves its way and
    // smoke comes out of it where it is; after, nothing drives the air (inviscid: the energy it
    // was given stays). Both backends alike.
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    settings.buoyancy = 0.0;
    // Its middle: -0.4 at 0.1 s.
    settings.emitters = {boxJet({-0.6, -0.15, 0.0}, {-0.2, 0.15, 0.0}, {1.5, 0.0, 0.0}, 0.1,
                                {{0.0, {-0.5, 0.0, 0.0}}, {0.2, {-0.3, 0.0, 0.0}}})};
    settings.integrator = Integrator::Midpoint;
    {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask, true);
        reference::Simulation cpu(disk.cache, *disk.coefficients, settings, disk.smokeMask);
        device.advanceSteps(5);
        cpu.advanceSteps(5);
        const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
        const double error =
            (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
        const MacGrid grid = MacGrid::fromSpec(disk.cache.grid);
        const auto cellAt = [&](int axis, double x) {
            return int((x - grid.origin[axis]) / grid.spacing[axis]);
        };
        const double inside =
            cpu.faceVelocity()[std::size_t(grid.faceIndex(0, cellAt(0, -0.4), cellAt(1, 0.0), 0))];
        const double energy = cpu.velocity().squaredNorm();
        const double densityError = maxDifference(device.smoke().density, cpu.smoke().density) /
                                    maxAbs(cpu.smoke().density);
        std::cout << "moving jet, 5 steps: relative differences: modes " << error << ", density "
                  << densityError << "; fluid x velocity inside the jet " << inside
                  << " (jet: 1.5)\n";
        EXPECT_LE(error, 1e-4);
        EXPECT_LE(densityError, 1e-4);
        EXPECT_GT(inside, 0.5) << "the air inside moves with the jet";
        device.advanceSteps(5);
        cpu.advanceSteps(5);
        EXPECT_NEAR(cpu.velocity().squaredNorm() / energy, 1.0, 1e-3)
            << "the jet is off: nothing drives the air";
        EXPECT_LE((device.velocity() - cpu.velocity()).lpNorm<Eigen::Infinity>() /
                      cpu.velocity().lpNorm<Eigen::Infinity>(),
                  1e-4);
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, AMeshSourceMatchesTheCpuReference) {
    // The hot ball's source replaced by a mesh's shell (a level set of a ball of radius 0.3 low in
    // the unit ball, as MeshSolids would sample it) that also blows upward: its emission and its
    // jet region (a mesh region in world coordinates) alike on both backends.
    const RunInputs& ball = hotBall();
    SimulationSettings settings = ball.settings;
    auto solid = std::make_shared<SolidLevelSet>();
    solid->spacing = 0.04;
    solid->origin = {-0.4, -0.4, -0.95};
    solid->samples = {21, 21, 21};
    for (int z = 0; z < 21; ++z)
        for (int y = 0; y < 21; ++y)
            for (int x = 0; x < 21; ++x)
                solid->depth.push_back(float(
                    0.3 - std::hypot(-0.4 + 0.04 * x, -0.4 + 0.04 * y, -0.95 + 0.04 * z + 0.55)));
    SmokeEmitter shell;
    shell.shape = EmitterShape::Mesh;
    shell.levelSet = solid;
    shell.thickness = 0.1;
    shell.densityRate = 2.0;
    shell.temperatureRate = 1.0;
    shell.velocity = Vec3{0.0, 0.0, 0.8};
    settings.emitters = {shell};
    {
        device::Simulation device(context(), ball.cache, *ball.coefficients, settings,
                                  ball.smokeMask, true);
        reference::Simulation cpu(ball.cache, *ball.coefficients, settings, ball.smokeMask);
        device.advanceFrame();
        cpu.advanceFrame();
        const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
        ASSERT_GT(expected.norm(), 0.0);
        const double error =
            (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
        const double densityError = maxDifference(device.smoke().density, cpu.smoke().density) /
                                    maxAbs(cpu.smoke().density);
        std::cout << "mesh source, 5 steps: relative max differences: modes " << error
                  << ", density " << densityError << "\n";
        EXPECT_LE(error, 1e-4);
        EXPECT_LE(densityError, 1e-4);
        // Little smoke at the shell's centre: it emits from its shell alone (in 0.1 s the flow
        // carries smoke by far less than the shell's inner radius, 0.2).
        const MacGrid grid = MacGrid::fromSpec(ball.cache.grid).refined(settings.smokeScale);
        const auto cellAt = [&](int axis, double x) {
            return int((x - grid.origin[axis]) / grid.spacing[axis]);
        };
        EXPECT_LT(cpu.smoke().density[std::size_t(
                      grid.cellIndex(cellAt(0, 0.0), cellAt(1, 0.0), cellAt(2, -0.55)))],
                  0.1 * maxAbs(cpu.smoke().density));
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, AClosedFormBoxRunsOnItsTransformsAndFollowsTheCpuReference) {
    // A whole box with free-slip walls: closed-form modes, no columns on either side; buoyant
    // smoke and a ball crossing the box full of smoke, which keeps none inside.
    SceneSpec scene = testing::gridScene({12, 10, 9}, {0.0, 0.0, 0.0}, {1.2, 1.0, 0.9}, 3);
    scene.name = "closed-form box";
    scene.basis.velocityModes = {{1, 80}};
    scene.basis.scalarModes = 0;
    scene.simulation.dt = 0.02;
    scene.output.stepsPerFrame = 5;
    scene.smoke.buoyancy = 2.0;
    SourceSpec source;
    source.shape = testing::ball({0.6, 0.5, 0.15}, 0.12);
    source.density = source.temperature = 1.0;
    scene.sources = {source};
    const RunInputs run = testing::sharedRun(scene);
    ASSERT_EQ(run.cache.velocity.source, BasisSource::ClosedForm);
    ASSERT_EQ(run.cache.velocity.modes.cols(), 0);
    SimulationSettings settings = run.settings;
    ObstacleSpec ball;
    ball.radius = 0.15;
    ball.path = {{0.0, {0.3, 0.5, 0.5}}, {1.0, {0.9, 0.5, 0.5}}};
    settings.obstacles = {MovingObstacle{ball}};
    {
        device::Simulation device(context(), run.cache, *run.coefficients, settings, run.smokeMask,
                                  true);
        reference::Simulation cpu(run.cache, *run.coefficients, settings, run.smokeMask);
        // The box full of smoke at 0.1 but where the ball starts, which the ball must push.
        const MacGrid& grid = cpu.smokeGrid();
        SmokeFields smoke{std::vector<double>(std::size_t(grid.cellCount()), 0.1),
                          std::vector<double>(std::size_t(grid.cellCount()), 0.0)};
        for (int z = 0; z < grid.cells[2]; ++z)
            for (int y = 0; y < grid.cells[1]; ++y)
                for (int x = 0; x < grid.cells[0]; ++x)
                    if (settings.obstacles[0].covers(testing::cellCentre(grid, x, y, z),
                                                     settings.obstacles[0].poseAt(0.0), grid))
                        smoke.density[std::size_t(grid.cellIndex(x, y, z))] = 0.0;
        const Eigen::VectorXd still = Eigen::VectorXd::Zero(cpu.velocity().size());
        device.restore(0.0, still, smoke);
        cpu.restore(0.0, still, smoke);
        FrameStats stats;
        for (int frame = 0; frame < 2; ++frame) {
            stats = device.advanceFrame();
            cpu.advanceFrame();
        }
        const Eigen::VectorXd v = device.velocity(), expected = cpu.velocity();
        ASSERT_GT(expected.norm(), 0.0);
        const double error =
            (v - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
        const double faceError =
            maxDifference(device.faceVelocity(), cpu.faceVelocity()) / maxAbs(cpu.faceVelocity());
        const double densityError = maxDifference(device.smoke().density, cpu.smoke().density) /
                                    maxAbs(cpu.smoke().density);
        std::cout << "closed-form box, 10 steps: relative max differences: modes " << error
                  << ", grid velocity " << faceError << ", density " << densityError
                  << "; device ms per frame: forces " << stats.forcesMs << ", reconstruction "
                  << stats.reconstructionMs << ", obstacles " << stats.obstaclesMs << "\n";
        EXPECT_LE(error, 1e-4);
        EXPECT_LE(faceError, 1e-4);
        EXPECT_LE(densityError, 1e-4);
        // The ball pushed the smoke it met, on both backends: none inside it.
        EXPECT_EQ(maxInside(device, settings.obstacles[0]), 0.0);
        EXPECT_EQ(maxInside(cpu, settings.obstacles[0]), 0.0);
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, AWindMatchesTheCpuReference) {
    // A still ball in a wind through a closed-form box full of smoke, a source upstream and
    // tracers: the modes' D v, the wind added to each reconstruction, the open sides and the
    // clean air coming in upstream, on the device as on the CPU. The wind crosses two axes, so
    // inflow and outflow meet at the corners; a boundary layer over the floor; and a uniform wind
    // round a [[domain]] hole (the cache's potential flow, its vorticity-form term); under an
    // open top; and round a no-slip hole in a viscous fluid (the modes relax toward the held
    // flow's Stokes correction).
    for (const int variant : {0, 1, 2, 3, 4, 5}) {
        const int dim = variant == 1 ? 3 : 2;
        SceneSpec scene =
            dim == 2 ? testing::gridScene({32, 16, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2)
                     : testing::gridScene({12, 10, 9}, {0.0, 0.0, 0.0}, {1.2, 1.0, 0.9}, 3);
        scene.name = "windy";
        scene.basis.velocityModes = {{1, dim == 2 ? 60 : 80}};
        scene.basis.scalarModes = 0;
        scene.simulation.dt = 0.02;
        scene.output.stepsPerFrame = 5;
        scene.wind = variant == 0   ? WindSpec{{0.8, -0.3, 0.0}}
                     : variant == 1 ? WindSpec{{0.5, 0.0, -0.4}}
                     : variant == 2 ? WindSpec{{0.8, 0.0, 0.0}, WindProfile::BoundaryLayer, 0.4}
                                    : WindSpec{{0.8, 0.2, 0.0}};
        if (variant >= 3)
            scene.domain = {testing::box({-1.0, -1.0, 0.0}, {3.0, 2.0, 0.0}),
                            testing::ball({1.45, 0.55, 0.0}, 0.17, CsgOp::Subtract)};
        if (variant == 4) {
            scene.grid.open[3] = true;
            scene.wind = WindSpec{{0.8, 0.0, 0.0}};
        }
        if (variant == 5) {
            scene.basis.wall = WallKind::NoSlip;
            scene.simulation.viscosity = 0.05;
        }
        SourceSpec source;
        source.shape = testing::ball(dim == 2 ? Vec3{0.3, 0.5, 0.0} : Vec3{0.25, 0.5, 0.6}, 0.12);
        source.density = source.temperature = 1.0;
        scene.sources = {source};
        const RunInputs run = testing::sharedRun(scene);
        ASSERT_EQ(run.cache.velocity.source,
                  variant >= 3 ? BasisSource::Eigensolve : BasisSource::ClosedForm);
        ASSERT_EQ(run.cache.windBase.size(), variant >= 3 ? 4u : 0u);
        SimulationSettings settings = run.settings;
        ASSERT_TRUE(settings.wind.has_value());
        // Off the face lattice: a face centre at exactly the radius is covered or not by the
        // last bit of float or double.
        ObstacleSpec ball;
        ball.radius = 0.153;
        const Vec3 centre = dim == 2 ? Vec3{0.913, 0.487, 0.0} : Vec3{0.613, 0.487, 0.452};
        ball.path = {{0.0, centre}, {1.0, centre}};
        settings.obstacles = {MovingObstacle{ball}};
        ParticleSetSpec tracers;
        tracers.region = testing::ball(centre, 0.35);
        tracers.count = 200;
        settings.particles = {tracers};
        {
            device::Simulation device(context(), run.cache, *run.coefficients, settings,
                                      run.smokeMask, true);
            reference::Simulation cpu(run.cache, *run.coefficients, settings, run.smokeMask);
            // Before any step the air is the wind alone on both.
            EXPECT_LE(maxDifference(device.faceVelocity(), cpu.faceVelocity()), 1e-7);
            const MacGrid& grid = cpu.smokeGrid();
            const SmokeFields smoke{std::vector<double>(std::size_t(grid.cellCount()), 0.1),
                                    std::vector<double>(std::size_t(grid.cellCount()), 0.0)};
            const Eigen::VectorXd still = Eigen::VectorXd::Zero(cpu.velocity().size());
            device.restore(0.0, still, smoke);
            cpu.restore(0.0, still, smoke);
            for (int frame = 0; frame < 2; ++frame) {
                device.advanceFrame();
                cpu.advanceFrame();
            }
            ASSERT_GT(cpu.velocity().norm(), 0.0) << "the ball disturbed the wind";
            const BackendDifferences d = differences(device, cpu);
            const std::vector<double> density = cpu.smoke().density;
            std::cout << dim << "D wind"
                      << (variant == 2   ? " in a boundary layer"
                          : variant == 3 ? " round a domain hole"
                          : variant == 4 ? " round a domain hole under an open top"
                          : variant == 5 ? " round a no-slip domain hole, viscous"
                                         : "")
                      << ", 10 steps: relative max differences: modes " << d.modes
                      << ", grid velocity " << d.faceVelocity << ", density " << d.density
                      << "; particles " << d.particles << "\n";
            EXPECT_LE(d.modes, 1e-4);
            EXPECT_LE(d.faceVelocity, 1e-4);
            EXPECT_LE(d.density, 1e-4);
            EXPECT_LE(d.particles, 1e-4);
            // Clean air came in upstream (not a run that ignores the wind's sides): the first
            // column of cells along x holds less smoke than the box did.
            double inflowColumn = 0.0;
            int cells = 0;
            for (int z = 0; z < grid.cells[2]; ++z)
                for (int y = 0; y < grid.cells[1]; ++y, ++cells)
                    inflowColumn += density[std::size_t(grid.cellIndex(0, y, z))];
            EXPECT_LT(inflowColumn / cells, 0.05);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SimulationTest, InflowsMatchTheCpuReference) {
    // 2D: a burner jet through an open floor (its air hot, smoky and fuelled, burning) and a
    // vent letting hazy air in at the open top; 3D: two smoke rakes upstream of a wind, the
    // second switched on after three steps over the first (which wins where they overlap).
    // The ghosts of both pairs, switched as the inflows start, and the jet's region over the
    // open floor's faces (which the device's correction once skipped as walls), on the device as
    // on the CPU, with MacCormack and with the conservative fluxes (a smoke grid twice as fine
    // in 2D).
    for (const int dim : {2, 3}) {
        SceneSpec scene =
            dim == 2 ? testing::gridScene({12, 16, 1}, {0.0, 0.0, 0.0}, {0.75, 1.0, 0.0}, 2)
                     : testing::gridScene({12, 8, 8}, {0.0, 0.0, 0.0}, {1.5, 1.0, 1.0}, 3);
        scene.name = "inflows";
        scene.basis.velocityModes = {{1, dim == 2 ? 40 : 60}};
        scene.basis.scalarModes = 0;
        scene.simulation.dt = 0.02;
        scene.output.stepsPerFrame = 5;
        InflowSpec first, second;
        if (dim == 2) {
            scene.grid.open = {false, false, true, true, false, false};
            scene.fire = FireSpec{0.5, 4.0, 1.0, 0.5};
            scene.smoke.buoyancy = 1.0;
            first.side = 2;
            first.shape = testing::box({0.271, -0.1, 0.0}, {0.477, 0.063, 0.0});
            first.velocity = Vec3{0.0, 1.5, 0.0};
            first.density = 1.0;
            first.temperature = 1.0;
            first.fuel = 0.5;
            second.side = 3;
            second.shape = testing::ball({0.203, 1.0, 0.0}, 0.171);
            second.density = 0.3;
        } else {
            WindSpec wind;
            wind.velocity = {1.0, 0.0, 0.0};
            scene.wind = wind;
            scene.smoke.buoyancy = 1.0;  // the second rake's warm air rises
            first.side = second.side = 0;
            first.shape = testing::ball({0.0, 0.413, 0.521}, 0.237);
            first.density = 1.0;
            second.shape = testing::box({-0.1, 0.287, 0.113}, {0.1, 0.713, 0.489});
            second.density = 0.5;
            second.temperature = 2.0;
            second.start = 0.06;
        }
        scene.inflows = {first, second};
        scene.smoke.resolutionScale = dim == 2 ? 2 : 1;
        const RunInputs run = testing::sharedRun(scene);
        for (const AdvectionScheme scheme :
             {AdvectionScheme::MacCormack, AdvectionScheme::Conservative}) {
            SimulationSettings settings = run.settings;
            settings.advection = scheme;
            device::Simulation device(context(), run.cache, *run.coefficients, settings,
                                      run.smokeMask, true);
            reference::Simulation cpu(run.cache, *run.coefficients, settings, run.smokeMask);
            for (int frame = 0; frame < 2; ++frame) {
                device.advanceFrame();
                cpu.advanceFrame();
            }
            const BackendDifferences d = differences(device, cpu);
            const SmokeFields smoke = cpu.smoke(), onDevice = device.smoke();
            const double temperature =
                maxDifference(onDevice.temperature, smoke.temperature) / maxAbs(smoke.temperature);
            const double fuel =
                dim == 2 ? maxDifference(onDevice.fuel, smoke.fuel) / maxAbs(smoke.fuel) : 0.0;
            std::cout << dim << "D inflows, scheme " << int(scheme)
                      << ", 10 steps: relative max differences: modes " << d.modes
                      << ", grid velocity " << d.faceVelocity << ", density " << d.density
                      << ", temperature " << temperature << ", fuel " << fuel << "; the most smoke "
                      << maxAbs(smoke.density) << "\n";
            EXPECT_LE(d.modes, 1e-4);
            EXPECT_LE(d.faceVelocity, 1e-4);
            EXPECT_LE(d.density, 1e-4);
            EXPECT_LE(temperature, 1e-4);
            EXPECT_LE(fuel, 1e-4);
            EXPECT_GT(maxAbs(smoke.density), 0.5) << "the inflows' smoke came in";
            if (dim == 2) {
                EXPECT_GT(maxAbs(smoke.fuel), 0.1) << "and the burner's fuel";
            }
        }
        expectNoValidationMessages();
    }
}

TEST_P(SimulationTest, ConservativeSmokeKeepsItsMassOnTheDevice) {
    // A periodic channel round a disk (cut cells, a seam along x), swirled and full of a blob of
    // smoke, conservative fluxes at twice the basis resolution: nothing crosses a side, so the
    // device keeps the smoke's mass to float round-off, as the CPU reference to double's.
    SceneSpec scene = testing::periodicChannelScene(16);
    scene.name = "conservative channel";
    scene.basis.velocityModes = {{1, 30}};
    scene.basis.scalarModes = 0;
    scene.simulation.dt = 0.02;
    scene.output.stepsPerFrame = 10;
    scene.smoke.resolutionScale = 2;
    scene.smoke.advection = AdvectionScheme::Conservative;
    const RunInputs run = testing::sharedRun(scene);
    device::Simulation device(context(), run.cache, *run.coefficients, run.settings, run.smokeMask,
                              true);
    reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
    const MacGrid& grid = cpu.smokeGrid();
    std::vector<double> blob = testing::gaussianBlob(grid, {1.6, 0.5, 0.0}, 0.25);
    for (std::size_t c = 0; c < blob.size(); ++c) blob[c] *= run.smokeMask[c] != 0;
    const SmokeFields smoke{blob, std::vector<double>(blob.size(), 0.0)};
    RandomVelocitySpec swirl;
    swirl.energy = 0.2;
    const Eigen::VectorXd v0 = randomVelocity(run.coefficients->size(), swirl);
    device.restore(0.0, v0, smoke);
    cpu.restore(0.0, v0, smoke);
    const auto mass = [](const std::vector<double>& field) {
        double sum = 0.0;
        for (const double value : field) sum += value;
        return sum;
    };
    const double before = mass(blob);
    for (int frame = 0; frame < 2; ++frame) {
        device.advanceFrame();
        cpu.advanceFrame();
    }
    const std::vector<double> onDevice = device.smoke().density, reference = cpu.smoke().density;
    const double moved = maxDifference(reference, blob) / maxAbs(blob);
    const double drift = std::abs(mass(onDevice) - before) / before;
    const double difference = maxDifference(onDevice, reference) / maxAbs(reference);
    std::cout << "conservative channel, 20 steps: the smoke moved " << moved
              << " of its peak; mass drift on the device " << drift << ", on the CPU "
              << std::abs(mass(reference) - before) / before << "; device = CPU to " << difference
              << "\n";
    EXPECT_GT(moved, 0.05) << "the swirl carried the smoke";
    EXPECT_LE(drift, 1e-6);
    EXPECT_LE(std::abs(mass(reference) - before), 1e-13 * before);
    EXPECT_LE(difference, 1e-4);
    expectNoValidationMessages();
}

TEST_P(SimulationTest, OpenSidesMatchTheCpuReference) {
    // A hot source under an open top (3D) and a box open at both ends with the flow straight
    // through it (2D), full of smoke: the open sides' faces in each reconstruction, the sampling
    // across them and the clean air they take in, on the device as on the CPU.
    for (const int dim : {2, 3}) {
        SceneSpec scene =
            dim == 2 ? testing::gridScene({12, 16, 1}, {0.0, 0.0, 0.0}, {0.75, 1.0, 0.0}, 2)
                     : testing::gridScene({8, 8, 10}, {0.0, 0.0, 0.0}, {0.8, 0.8, 1.0}, 3);
        scene.name = "open";
        scene.grid.open = dim == 2 ? std::array<bool, 6>{false, false, true, true, false, false}
                                   : std::array<bool, 6>{false, false, false, false, false, true};
        scene.basis.velocityModes = {{1, dim == 2 ? 40 : 60}};
        scene.basis.scalarModes = 0;
        scene.simulation.dt = 0.02;
        scene.output.stepsPerFrame = 5;
        SourceSpec source;
        // Off the smoke lattice: a sample point at exactly the radius is covered or not by the
        // last bit of float or double.
        source.shape =
            testing::ball(dim == 2 ? Vec3{0.371, 0.213, 0.0} : Vec3{0.407, 0.389, 0.213}, 0.123);
        source.density = source.temperature = 1.0;
        scene.sources = {source};
        scene.smoke.buoyancy = 1.0;
        // Tracers under the top, some carried out through it.
        ParticleSetSpec tracers;
        tracers.region = dim == 2 ? testing::box({0.05, 0.88, 0.0}, {0.7, 0.995, 0.0})
                                  : testing::box({0.05, 0.05, 0.88}, {0.75, 0.75, 0.995});
        tracers.count = 200;
        scene.particles = {tracers};
        const RunInputs run = testing::sharedRun(scene);
        ASSERT_EQ(run.cache.velocity.harmonic, dim == 2 ? 1 : 0);
        {
            device::Simulation device(context(), run.cache, *run.coefficients, run.settings,
                                      run.smokeMask, true);
            reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
            const MacGrid& grid = cpu.smokeGrid();
            const SmokeFields smoke{std::vector<double>(std::size_t(grid.cellCount()), 0.1),
                                    std::vector<double>(std::size_t(grid.cellCount()), 0.0)};
            Eigen::VectorXd start = Eigen::VectorXd::Zero(cpu.velocity().size());
            start[0] = 0.5;  // 2D: the flow straight through; 3D: a slow first mode
            device.restore(0.0, start, smoke);
            cpu.restore(0.0, start, smoke);
            for (int frame = 0; frame < 2; ++frame) {
                device.advanceFrame();
                cpu.advanceFrame();
            }
            const BackendDifferences d = differences(device, cpu);
            const std::vector<double> density = cpu.smoke().density;
            std::cout << dim << "D open sides, 10 steps: relative max differences: modes "
                      << d.modes << ", grid velocity " << d.faceVelocity << ", density "
                      << d.density << "; particles " << d.particles << " (" << d.left
                      << " of 200 left through the top)\n";
            EXPECT_LE(d.modes, 1e-4);
            EXPECT_LE(d.faceVelocity, 1e-4);
            EXPECT_LE(d.density, 1e-4);
            EXPECT_LE(d.particles, 1e-4);
            if (dim == 2) {
                EXPECT_GT(d.left, 0);
            }
            // Air crossed the top: its faces carry flux (the last layer of normal-up faces).
            const MacGrid air = MacGrid::fromSpec(run.cache.grid);
            const int up = dim - 1;
            const std::int64_t layer = air.faceCount(up) / air.faceExtent(up)[up];
            double topFlux = 0.0;
            for (std::int64_t f = air.faceOffset(up) + air.faceCount(up) - layer;
                 f < air.faceOffset(up) + air.faceCount(up); ++f)
                topFlux += std::abs(cpu.faceVelocity()[std::size_t(f)]);
            EXPECT_GT(topFlux, 0.0);
            if (dim == 2) {
                // Clean air came in at the bottom: its row holds less smoke than the box did.
                double bottomRow = 0.0;
                for (int x = 0; x < grid.cells[0]; ++x)
                    bottomRow += density[std::size_t(grid.cellIndex(x, 0, 0))];
                EXPECT_LT(bottomRow / grid.cells[0], 0.09);
            }
        }
        expectNoValidationMessages();
    }
}

TEST_P(SimulationTest, EmittersFollowTheirTimeWindows) {
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    settings.buoyancy = 0.0;  // still fluid: the smoke only accumulates
    settings.stepsPerFrame = 1;
    settings.emitters[0].start = 0.05;  // steps 3 and 4 of 0.02 (t = 0.06, 0.08) emit
    settings.emitters[0].end = 0.09;
    {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask);
        reference::Simulation cpu(disk.cache, *disk.coefficients, settings, disk.smokeMask);
        std::vector<double> masses;
        for (int step = 0; step < 6; ++step) {
            device.advanceFrame();
            cpu.advanceFrame();
            double mass = 0.0;
            for (double d : device.smoke().density) mass += d;
            masses.push_back(mass);
            EXPECT_LE(maxDifference(device.smoke().density, cpu.smoke().density), 1e-6)
                << "step " << step;
        }
        EXPECT_EQ(masses[2], 0.0) << "before the window";
        EXPECT_GT(masses[3], 0.0);
        EXPECT_NEAR(masses[4], 2.0 * masses[3], 1e-4 * masses[3]) << "two steps inside the window";
        EXPECT_EQ(masses[5], masses[4]) << "after the window";
    }
    expectNoValidationMessages();
}

TEST_P(SimulationTest, StepsRecordedOnceGiveTheStepsRecordedEachTime) {
    // Hot smoke rising in the disk, its emitter switching on and off, a splat stirring for a
    // while, the viscosity, integrator and timing changed between steps, MacCormack's fields
    // swapped each step: every change the kept steps must notice, against steps recorded afresh.
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    settings.stepsPerFrame = 1;
    settings.emitters[0].start = 0.05;
    settings.emitters[0].end = 0.13;
    const auto run = [&](device::StepRecording recording) {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask, true, recording);
        std::vector<Eigen::VectorXd> velocities;
        std::vector<std::vector<double>> densities;
        const ForceSplat push{{0.1, -0.2, 0.0}, {3.0, 1.0, 0.0}, 0.3};
        for (int step = 0; step < 16; ++step) {
            if (step == 4) device.setSplats(std::span(&push, 1));
            if (step == 7) device.setSplats({});
            if (step == 9) device.setViscosity(0.01);
            if (step == 11) device.setIntegrator(Integrator::Linearized);
            if (step == 12) device.setTiming(false);
            if (step == 14) device.setTiming(true);
            device.advanceSteps(1);
            velocities.push_back(device.velocity());
            densities.push_back(device.smoke().density);
        }
        return std::make_pair(velocities, densities);
    };
    const auto once = run(device::StepRecording::Once);
    const auto each = run(device::StepRecording::EveryStep);
    for (std::size_t step = 0; step < once.first.size(); ++step) {
        EXPECT_EQ(once.first[step], each.first[step]) << "velocity after step " << step + 1;
        EXPECT_EQ(once.second[step], each.second[step]) << "smoke after step " << step + 1;
    }
    EXPECT_GT(once.second.back().size(), 0u);
    EXPECT_GT(*std::max_element(once.second.back().begin(), once.second.back().end()), 0.0);
    expectNoValidationMessages();
}

TEST_P(SimulationTest, JetsRecordedOnceGiveTheStepsRecordedEachTime) {
    // A jet crossing the disk fast (0.12 a step, more than a cell) for 12 of 16 steps: a kept
    // step walks the faces of where it will be over the next steps, is resubmitted while it stays
    // there and recorded again when it leaves, or when it stops; the same steps as recorded
    // afresh each time.
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    settings.stepsPerFrame = 1;
    settings.emitters = {boxJet({-0.15, -0.15, 0.0}, {0.15, 0.15, 0.0}, {0.0, 1.5, 0.0},
                                12 * settings.dt,
                                {{0.0, {-0.7, -0.2, 0.0}}, {0.2, {0.5, -0.2, 0.0}}})};
    const auto run = [&](device::StepRecording recording) {
        device::Simulation device(context(), disk.cache, *disk.coefficients, settings,
                                  disk.smokeMask, true, recording);
        std::vector<Eigen::VectorXd> velocities;
        std::vector<std::vector<double>> densities;
        int resubmitted = 0;
        for (int step = 0; step < 16; ++step) {
            resubmitted += device.advanceSteps(1).resubmittedSteps;
            velocities.push_back(device.velocity());
            densities.push_back(device.smoke().density);
        }
        return std::make_tuple(velocities, densities, resubmitted);
    };
    const auto [onceVelocities, onceDensities, resubmitted] = run(device::StepRecording::Once);
    const auto [eachVelocities, eachDensities, afresh] = run(device::StepRecording::EveryStep);
    for (std::size_t step = 0; step < onceVelocities.size(); ++step) {
        EXPECT_EQ(onceVelocities[step], eachVelocities[step]) << "velocity after step " << step + 1;
        EXPECT_EQ(onceDensities[step], eachDensities[step]) << "smoke after step " << step + 1;
    }
    EXPECT_EQ(afresh, 0);
    // A kept step per parity: 14 resubmissions if nothing ever changed.
    EXPECT_GT(resubmitted, 4) << "the kept steps ran while the jet stayed in their box";
    EXPECT_LT(resubmitted, 12) << "recorded again as the jet left their box and stopped";
    EXPECT_GT(onceVelocities.back().norm(), 0.0);
    expectNoValidationMessages();
}

/// Tracers in a ball low in the disk (or ball) and leaves blown in at a rate from a box.
std::vector<ParticleSetSpec> tracersAndLeaves(int dim) {
    ParticleSetSpec tracers;
    tracers.region = testing::ball(dim == 2 ? Vec3{0.2, -0.3, 0.0} : Vec3{0.2, 0.0, -0.3}, 0.3);
    tracers.count = 300;
    ParticleSetSpec leaves;
    leaves.region.kind = ShapeKind::Box;
    leaves.region.min = {-0.4, -0.4, dim == 2 ? 0.0 : -0.4};
    leaves.region.max = {0.4, 0.4, dim == 2 ? 0.0 : 0.4};
    leaves.rate = 1500.0;
    leaves.drag = 3.0;
    leaves.gravity = 2.0;
    leaves.seed = 5;
    return {tracers, leaves};
}

TEST_P(SimulationTest, ParticlesFollowTheCpuReference) {
    // Tracers and inertial leaves in the hot disk and ball, with a ball obstacle crossing them:
    // the device's float32 steps stay with the CPU's double ones.
    for (const RunInputs* run : {&hotDisk(), &hotBall()}) {
        const int dim = run->scene.grid.dim;
        SimulationSettings settings = run->settings;
        settings.particles = tracersAndLeaves(dim);
        ObstacleSpec ball;
        ball.radius = 0.2;
        ball.path = {{0.0, {-0.5, 0.1, 0.0}}, {1.0, {0.5, 0.1, 0.0}}};
        settings.obstacles = {MovingObstacle{ball}};
        {
            device::Simulation device(context(), run->cache, *run->coefficients, settings,
                                      run->smokeMask, true);
            reference::Simulation cpu(run->cache, *run->coefficients, settings, run->smokeMask);
            RandomVelocitySpec swirl;
            swirl.energy = 0.05;
            const Eigen::VectorXd v0 = randomVelocity(run->coefficients->size(), swirl);
            device.setVelocity(v0);
            cpu.setVelocity(v0);
            FrameStats stats;
            for (int frame = 0; frame < 2; ++frame) {
                stats = device.advanceFrame();
                cpu.advanceFrame();
            }
            const Particles onDevice = device.particles(), expected = cpu.particles();
            // 300 tracers, and 1500 / s × 10 steps of 0.02.
            ASSERT_EQ(expected.size(), 300u + 300u);
            ASSERT_EQ(onDevice.size(), expected.size());
            EXPECT_EQ(onDevice.set, expected.set);
            double worst = 0.0, fastest = 0.0;
            int apart = 0;
            for (std::size_t i = 0; i < expected.size(); ++i) {
                double distance = 0.0;
                for (int a = 0; a < 3; ++a) {
                    distance = std::max(distance, std::abs(onDevice.position[3 * i + a] -
                                                           expected.position[3 * i + a]));
                    fastest = std::max(fastest, std::abs(expected.velocity[3 * i + a]));
                }
                worst = std::max(worst, distance);
                apart += distance > 1e-4 ? 1 : 0;
                const Vec3 x{expected.position[3 * i], expected.position[3 * i + 1],
                             expected.position[3 * i + 2]};
                EXPECT_FALSE(settings.obstacles[0].covers(x, settings.obstacles[0].poseAt(0.2),
                                                          cpu.smokeGrid()));
                EXPECT_TRUE(inFluidCell(cpu.smokeGrid(), run->smokeMask, x));
            }
            std::cout << dim << "D, 10 steps, 600 particles: largest position difference " << worst
                      << ", " << apart
                      << " apart by more than 1e-4; device ms per frame: " << stats.particlesMs
                      << "\n";
            EXPECT_GT(fastest, 0.1) << "the air moved them";
            // A step across a wall cell's edge may go either way in float and double.
            EXPECT_LE(apart, 6);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SimulationTest, ParticlesASolidPushesIntoTheWallSlideBackIntoTheFluid) {
    // A ball sweeps tracers against the curved wall: those it pushes out past the wall slide
    // from where they started the step (the device lists them near the solid and finishes them
    // apart from the rest: shaders/ParticleStep.glsl), as on the CPU.
    for (const RunInputs* run : {&hotDisk(), &hotBall()}) {
        const int dim = run->scene.grid.dim;
        SimulationSettings settings = run->settings;
        ParticleSetSpec tracers;
        tracers.region = testing::ball({0.8, 0.0, 0.0}, 0.15);
        tracers.count = 400;
        settings.particles = {tracers};
        ObstacleSpec ball;
        ball.radius = 0.2;
        ball.path = {{0.0, {0.5, 0.0, 0.0}}, {0.2, {0.9, 0.0, 0.0}}};
        settings.obstacles = {MovingObstacle{ball}};
        {
            device::Simulation device(context(), run->cache, *run->coefficients, settings,
                                      run->smokeMask, true);
            reference::Simulation cpu(run->cache, *run->coefficients, settings, run->smokeMask);
            for (int frame = 0; frame < 2; ++frame) {
                device.advanceFrame();
                cpu.advanceFrame();
            }
            const Particles onDevice = device.particles(), expected = cpu.particles();
            ASSERT_EQ(onDevice.size(), expected.size());
            int apart = 0, movedByTheBall = 0;
            for (std::size_t i = 0; i < expected.size(); ++i) {
                double distance = 0.0;
                for (int a = 0; a < 3; ++a)
                    distance = std::max(distance, std::abs(onDevice.position[3 * i + a] -
                                                           expected.position[3 * i + a]));
                apart += distance > 1e-4 ? 1 : 0;
                const Vec3 x{onDevice.position[3 * i], onDevice.position[3 * i + 1],
                             onDevice.position[3 * i + 2]};
                EXPECT_TRUE(inFluidCell(cpu.smokeGrid(), run->smokeMask, x))
                    << dim << "D particle " << i << " at " << x[0] << ", " << x[1];
                movedByTheBall += std::hypot(x[1], x[2]) > 0.15 ? 1 : 0;
            }
            EXPECT_GT(movedByTheBall, 20) << dim << "D: the ball swept them aside";
            EXPECT_LE(apart, 8) << dim << "D";
        }
        expectNoValidationMessages();
    }
}

/// What a run keeps after a frame, as a checkpoint file holds it.
Checkpoint savedThroughAFile(const Simulator& simulator, int frame) {
    const testing::TestFolder folder;
    writeCheckpoint(folder / "run.resume",
                    {frame, simulator.time(), 0, simulator.velocity(), simulator.magneticField(),
                     simulator.carry(), simulator.smoke(), simulator.particles()});
    return readCheckpoint(folder / "run.resume");
}

TEST(SimulationResume, EveryBackendAndIntegratorContinuesBitForBitFromAnyStep) {
    // A run stopped after any step and resumed from what its checkpoint holds takes the steps of
    // the run that never stopped, to the bit: on the device and the CPU, with every integrator,
    // right after the first step too, and with the device's substeps set from a carry.
    const auto context = testing::makeVulkanContext(false);
    ASSERT_NE(context, nullptr);
    const RunInputs& disk = hotDisk();
    SimulationSettings settings = disk.settings;
    settings.stepsPerFrame = 1;
    // A ball crossing the smoke: its correction and the smoke it pushes resume too.
    ObstacleSpec ball;
    ball.radius = 0.15;
    ball.path = {{0.0, {-0.3, -0.5, 0.0}}, {1.0, {0.3, 0.2, 0.0}}};
    settings.obstacles = {MovingObstacle{ball}};
    // Particles too: tracers from the start, leaves at a rate, both through the checkpoint.
    settings.particles = tracersAndLeaves(2);
    RandomVelocitySpec swirl;
    swirl.energy = 0.05;
    const Eigen::VectorXd v0 = randomVelocity(disk.coefficients->size(), swirl);
    constexpr int kSteps = 8;
    struct Case {
        bool device;
        Integrator scheme;
        int substeps;
    };
    std::vector<Case> cases;
    for (const bool device : {true, false})
        for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                        Integrator::Trapezoidal, Integrator::Linearized})
            cases.push_back({device, scheme, 1});
    cases.push_back({true, Integrator::Midpoint, 4});
    for (const Case& c : cases) {
        settings.integrator = c.scheme;
        const std::string name = std::string(c.device ? "device " : "CPU ") +
                                 std::string(sceneKeyword(c.scheme)) + ", " +
                                 std::to_string(c.substeps) + " substeps";
        const auto make = [&]() -> std::unique_ptr<Simulator> {
            if (c.device)
                return std::make_unique<device::Simulation>(
                    *context, disk.cache, *disk.coefficients, settings, disk.smokeMask);
            return std::make_unique<reference::Simulation>(disk.cache, *disk.coefficients, settings,
                                                           disk.smokeMask);
        };
        const std::unique_ptr<Simulator> whole = make();
        whole->setVelocity(v0);
        if (c.substeps > 1) whole->setCarry({{}, {}, c.substeps, 0});
        std::vector<Checkpoint> saved;
        std::vector<int> iterations;  // of each step
        for (int step = 1; step <= kSteps; ++step) {
            iterations.push_back(whole->advanceFrame().maxIterations);
            saved.push_back(savedThroughAFile(*whole, step));
        }
        if (c.device && c.scheme == Integrator::Midpoint) {
            // One R held after the first step, two once two substeps converged.
            EXPECT_EQ(saved[0].carry.warmRhs.size(), c.substeps > 1 ? 2u : 1u) << name;
            EXPECT_EQ(saved[4].carry.warmRhs.size(), 2u) << name;
        }
        EXPECT_EQ(saved[0].carry.heldRate.size() != 0, c.scheme == Integrator::Linearized) << name;
        EXPECT_EQ(saved[4].carry.substeps, c.substeps) << name;
        for (int stop = 1; stop < kSteps; ++stop) {
            const Checkpoint& from = saved[std::size_t(stop - 1)];
            const std::unique_ptr<Simulator> resumed = make();
            resumed->restore(from.time, from.velocity, from.smoke);
            resumed->setCarry(from.carry);
            resumed->setParticles(from.particles);
            // The first step after the resume starts where the uninterrupted one did: as many
            // implicit iterations (a cold start takes more, and may still reach the same state).
            for (int step = stop + 1; step <= kSteps; ++step)
                EXPECT_EQ(resumed->advanceFrame().maxIterations, iterations[std::size_t(step - 1)])
                    << name << ", resumed after " << stop << ", step " << step;
            const StepCarry carry = resumed->carry(), expected = whole->carry();
            EXPECT_EQ(carry.heldRate, expected.heldRate) << name;
            EXPECT_EQ(carry.warmRhs, expected.warmRhs) << name;
            EXPECT_EQ(carry.substeps, expected.substeps) << name;
            EXPECT_EQ(carry.easySteps, expected.easySteps) << name;
            EXPECT_EQ(resumed->time(), whole->time()) << name;
            EXPECT_EQ(resumed->velocity(), whole->velocity()) << name << ", resumed after " << stop;
            EXPECT_EQ(resumed->smoke().density, whole->smoke().density)
                << name << ", resumed after " << stop;
            EXPECT_EQ(resumed->smoke().temperature, whole->smoke().temperature)
                << name << ", resumed after " << stop;
            const Particles particles = resumed->particles(),
                            expectedParticles = whole->particles();
            EXPECT_EQ(particles.size(), 300u + 8u * 30u) << name;
            EXPECT_EQ(particles.position, expectedParticles.position)
                << name << ", resumed after " << stop;
            EXPECT_EQ(particles.velocity, expectedParticles.velocity)
                << name << ", resumed after " << stop;
        }
    }
    // A carry the backend cannot take is refused: the CPU has no warm start nor substeps, the
    // device no schedule it would not make.
    reference::Simulation cpu(disk.cache, *disk.coefficients, settings, disk.smokeMask);
    EXPECT_THROW(cpu.setCarry({{}, {}, 4, 0}), Error);
    EXPECT_THROW(cpu.setCarry({{}, {Eigen::VectorXd::Zero(disk.coefficients->size())}, 1, 0}),
                 Error);
    device::Simulation gpu(*context, disk.cache, *disk.coefficients, settings, disk.smokeMask);
    EXPECT_THROW(gpu.setCarry({{}, {}, 3, 0}), Error);
    EXPECT_THROW(gpu.setCarry({{}, {}, 64, 0}), Error);
    EXPECT_THROW(gpu.setCarry({{}, {}, 2, -1}), Error);
    testing::expectNoValidationMessages(*context);
}

INSTANTIATE_TEST_SUITE_P(PlainAndValidated, SimulationTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
