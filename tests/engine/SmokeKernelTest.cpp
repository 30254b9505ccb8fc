/// @file SmokeKernelTest.cpp
/// shaders/smoke_advect.comp (SmokeAdvectionKernels, SmokeState) against the CPU reference
/// SmokeAdvection on the same float-rounded inputs: both schemes, 2D and 3D, smoke scale 1 and
/// 2, emitters, several steps in one submission, any workgroup size, grids split over several
/// dispatches, periodic axes; smoke outside Ω is exactly 0 and never read.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <optional>

#include <gtest/gtest.h>

#include "engine/device/SmokeAdvection.h"
#include "engine/device/SmokeState.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/simulation/WindTransport.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using device::SmokeAdvectionKernels;
using device::SmokeState;
using testing::kAdvectionSchemes;
using testing::schemeName;
using vulkan::CommandSequence;
using vulkan::DeviceBuffer;

std::vector<float> toFloat(const std::vector<double>& v) {
    return std::vector<float>(v.begin(), v.end());
}
std::vector<double> toDouble(const std::vector<float>& v) {
    return std::vector<double>(v.begin(), v.end());
}
void roundToFloat(std::vector<double>& v) {
    for (double& x : v) x = double(float(x));
}

struct SmokeSetup {
    int dim = 2;
    int cells = 32;  ///< basis cells per axis
    int scale = 1;
    AdvectionScheme scheme = AdvectionScheme::SemiLagrangian;
    int steps = 3;
    std::uint32_t workgroupSize = 64;
    bool timestamps = false;
    double maskRadius = 0.85;  ///< Ω: the disk (ball) of this radius; 2 covers the box
    int cellsZ = 0;            ///< basis cells along z in 3D when not 0 (else `cells`)
    /// Periodic axes: Ω is the box less the disk (ball) of radius 0.3 at the origin, the velocity
    /// the swirl plus a uniform flow across the seams, and a blob lies on them.
    std::array<bool, 3> periodic{false, false, false};
    /// A wind through the box ([wind]): the swirl halved plus the wind, its sides open and the
    /// upstream ones inflows of its air (SmokeState::setWind, SmokeAdvection::setWind).
    std::optional<WindSpec> wind{};
};

/// Emitters with binary-fraction parameters (exact in float32), one crossing the wall of Ω.
struct SmokeRun {
    SmokeFields device;     ///< the kernels' result
    SmokeFields reference;  ///< SmokeAdvection on the float-rounded inputs, rounded after each step
    std::vector<std::uint8_t> mask;
    std::vector<double> timesMs;
    std::size_t dispatches = 0;
};

/// `steps` steps of a random divergence-free swirl in a ball (disk) of radius 0.85, smoke blobs
/// and two emitters, recorded into one submission, in Ω the ball (disk) of radius s.maskRadius.
/// Cells outside Ω start as NaN: reading one would show in the result.
SmokeRun runSmoke(const vulkan::VulkanContext& context, const SmokeSetup& s, double dt = 0.02) {
    MacGrid basis = testing::smokeTestGrid(s.dim, s.cells);
    if (s.dim == 3 && s.cellsZ != 0) {
        basis.cells[2] = s.cellsZ;
        basis.spacing[2] = 2.0 / s.cellsZ;
    }
    basis.periodic = s.periodic;
    const bool periodic = basis.periodicBits() != 0;
    const MacGrid smoke = basis.refined(s.scale);
    SmokeRun run;
    run.mask = testing::ballMask(smoke, s.maskRadius);
    if (periodic) {
        const std::vector<std::uint8_t> hole = testing::ballMask(smoke, 0.3);
        for (std::size_t c = 0; c < hole.size(); ++c) run.mask[c] = !hole[c];
    }
    std::vector<double> velocity = testing::unitSwirlVelocity(basis, 0.8, 5);
    if (periodic) {
        const std::vector<double> uniform = testing::constantVelocity(basis, {0.75, -0.5, 0.625});
        for (std::size_t f = 0; f < velocity.size(); ++f)
            velocity[f] = 0.5 * velocity[f] + uniform[f];
    }
    if (s.wind) {
        for (double& u : velocity) u *= 0.5;
        addWind(basis, *s.wind, velocity);
    }
    roundToFloat(velocity);
    SmokeFields fields{
        testing::gaussianBlob(smoke, periodic ? Vec3{0.9, -0.95, 0.9} : Vec3{0.2, -0.1, 0.05}, 0.2),
        testing::gaussianBlob(smoke, {-0.3, 0.25, 0.0}, 0.15)};
    if (s.wind)  // smoke everywhere, so the clean air coming in shows at every side
        for (double& d : fields.density) d += 0.25;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t c = 0; c < run.mask.size(); ++c)
        if (!run.mask[c]) fields.density[c] = fields.temperature[c] = nan;
    roundToFloat(fields.density);
    roundToFloat(fields.temperature);
    const std::vector<SmokeEmitter> emitters = testing::smokeTestEmitters();

    reference::SmokeAdvection reference(basis, s.scale, run.mask);
    if (s.wind) reference.setWind(*s.wind);
    run.reference = fields;
    for (int step = 0; step < s.steps; ++step) {
        reference.step(velocity, dt, s.scheme, emitters, run.reference);
        roundToFloat(run.reference.density);  // the device stores float32 between steps
        roundToFloat(run.reference.temperature);
    }

    const SmokeAdvectionKernels kernels(context, s.workgroupSize);
    SmokeState state(context, basis, s.scale, run.mask);
    if (s.wind) state.setWind(*s.wind);
    state.upload(toFloat(fields.density), toFloat(fields.temperature));
    state.setEmitters(emitters);
    const DeviceBuffer velocityBuffer =
        DeviceBuffer::fromValues<float>(context, toFloat(velocity), "velocity");
    CommandSequence sequence(context, s.timestamps);
    for (int step = 0; step < s.steps; ++step)
        kernels.record(sequence, state, velocityBuffer, dt, s.scheme);
    run.dispatches = sequence.dispatchCount();
    sequence.submitAndWait();
    run.timesMs = sequence.dispatchTimesMs();
    std::vector<float> density(run.mask.size()), temperature(run.mask.size());
    state.download(density, temperature);
    run.device = {toDouble(density), toDouble(temperature)};
    return run;
}

/// max |device − reference| / max |reference|.
double relativeError(const std::vector<double>& device, const std::vector<double>& reference) {
    double error = 0.0, scale = 0.0;
    for (std::size_t c = 0; c < device.size(); ++c) {
        error = std::max(error, std::abs(device[c] - reference[c]));
        scale = std::max(scale, std::abs(reference[c]));
    }
    return error / scale;
}

/// No NaN anywhere and exactly 0 outside Ω.
void expectCleanOutside(const std::vector<double>& field, const std::vector<std::uint8_t>& mask,
                        const std::string& what) {
    for (std::size_t c = 0; c < field.size(); ++c) {
        ASSERT_FALSE(std::isnan(field[c]))
            << what << ": cell " << c << " is NaN (read outside Ω or never written)";
        if (!mask[c]) {
            ASSERT_EQ(field[c], 0.0) << what << ": smoke outside Ω at cell " << c;
        }
    }
}

double worstError(const SmokeRun& run, const std::string& what) {
    expectCleanOutside(run.device.density, run.mask, what + " density");
    expectCleanOutside(run.device.temperature, run.mask, what + " temperature");
    return std::max(relativeError(run.device.density, run.reference.density),
                    relativeError(run.device.temperature, run.reference.temperature));
}

class SmokeKernelTest : public testing::VulkanTest {};

TEST_P(SmokeKernelTest, EqualsTheCpuReferenceInFloat32) {
    for (const int dim : {2, 3})
        for (const int scale : {1, 2})
            for (const AdvectionScheme scheme : kAdvectionSchemes) {
                const std::string what =
                    std::to_string(dim) + "D x" + std::to_string(scale) + " " + schemeName(scheme);
                {
                    const SmokeRun run =
                        runSmoke(context(), {dim, dim == 2 ? 32 : 12, scale, scheme});
                    const double error = worstError(run, what);
                    std::cout << what << ", 3 steps: relative max error " << error << "\n";
                    EXPECT_LE(error, 1e-5) << what;
                }
                expectNoValidationMessages();
            }
}

TEST_P(SmokeKernelTest, PeriodicAxesEqualTheCpuReferenceInFloat32) {
    // x alone and with y (the face pairs wrap along x), y and z without x (the stencils' offsets
    // wrap in uint arithmetic), and the whole 3D torus.
    const std::vector<std::pair<int, std::array<bool, 3>>> cases{{2, {true, false, false}},
                                                                 {2, {true, true, false}},
                                                                 {3, {false, true, true}},
                                                                 {3, {true, true, true}}};
    for (const auto& [dim, periodic] : cases)
        for (const int scale : {1, 2})
            for (const AdvectionScheme scheme : kAdvectionSchemes) {
                const std::string what = std::to_string(dim) + "D periodic " +
                                         std::to_string(periodic[0]) + std::to_string(periodic[1]) +
                                         std::to_string(periodic[2]) + " x" +
                                         std::to_string(scale) + " " + schemeName(scheme);
                {
                    SmokeSetup setup{dim, dim == 2 ? 32 : 12, scale, scheme};
                    setup.maskRadius = 2.0;
                    setup.periodic = periodic;
                    setup.steps = 6;
                    const SmokeRun run = runSmoke(context(), setup);
                    const double error = worstError(run, what);
                    std::cout << what << ", 6 steps: relative max error " << error << "\n";
                    EXPECT_LE(error, 1e-5) << what;
                }
                expectNoValidationMessages();
            }
}

TEST_P(SmokeKernelTest, AWindsOpenSidesEqualTheCpuReferenceInFloat32) {
    // The sides a wind crosses read the velocity they carry, its upstream sides bring in clean
    // air: along x and y in 2D (every side open), along x and z in 3D beside y's walls, and
    // along a periodic axis (no side to open).
    // The last two bring smoke and heat in.
    struct Case {
        int dim;
        WindSpec wind;
        std::array<bool, 3> periodic;
    };
    WindSpec hazy{{0.7, 0.4, -0.5}};
    hazy.density = 0.625;
    hazy.temperature = -0.375;
    WindSpec warm{{0.8, -0.6, 0.0}};
    warm.temperature = 0.5;
    const std::vector<Case> cases{{2, WindSpec{{0.8, -0.6, 0.0}}, {false, false, false}},
                                  {3, WindSpec{{0.7, 0.0, -0.5}}, {false, false, false}},
                                  {3, hazy, {true, false, false}},
                                  {2, warm, {false, false, false}}};
    for (const Case& c : cases)
        for (const int scale : {1, 2})
            for (const AdvectionScheme scheme : kAdvectionSchemes) {
                const std::string what =
                    std::to_string(c.dim) + "D wind " + std::to_string(c.wind.velocity[0]) + "," +
                    std::to_string(c.wind.velocity[1]) + "," + std::to_string(c.wind.velocity[2]) +
                    " bringing " + std::to_string(c.wind.density) + "," +
                    std::to_string(c.wind.temperature) + " x" + std::to_string(scale) + " " +
                    schemeName(scheme);
                {
                    // 11 x 11 x 10 in 3D: a face total that is no whole number of texels, so
                    // the last faces' pairs (on an open side) come from a partial texel.
                    SmokeSetup setup{c.dim, c.dim == 2 ? 32 : 11, scale, scheme};
                    setup.cellsZ = c.dim == 3 ? 10 : 0;
                    setup.maskRadius = 2.0;
                    setup.periodic = c.periodic;
                    setup.wind = c.wind;
                    setup.steps = 6;
                    const SmokeRun run = runSmoke(context(), setup, 0.1);
                    const double error = worstError(run, what);
                    std::cout << what << ", 6 steps: relative max error " << error << "\n";
                    EXPECT_LE(error, 1e-5) << what;
                }
                expectNoValidationMessages();
            }
}

TEST_P(SmokeKernelTest, AUniformFlowCarriesABlobOnceAroundAPeriodicBoxBackToItsStart) {
    // SmokeAdvectionTest's journey on the device: a blob on the seam of a 2D torus, carried 0.4
    // cells a step by a harmonic flow, is back after a period, and its mass is kept (to float32).
    for (const AdvectionScheme scheme : kAdvectionSchemes) {
        {
            const MacGrid grid = testing::periodicSmokeTestGrid(2, 32);
            const std::vector<std::uint8_t> mask = testing::wholeMask(grid);
            const Vec3 start{0.96, -0.93, 0.0};
            const std::vector<double> blob = testing::gaussianBlob(grid, start, 0.2);
            const SmokeAdvectionKernels kernels(context());
            SmokeState state(context(), grid, 1, mask);
            state.upload(toFloat(blob), toFloat(blob));
            const DeviceBuffer velocity = DeviceBuffer::fromValues<float>(
                context(), toFloat(testing::diagonalFlow(grid)), "velocity");
            CommandSequence sequence(context());
            for (int step = 0; step < 80; ++step)
                kernels.record(sequence, state, velocity, 0.0125, scheme);
            sequence.submitAndWait();
            std::vector<float> density(mask.size()), temperature(mask.size());
            state.download(density, temperature);
            const reference::SmokeAdvection reference(grid, 1, mask);
            const std::vector<double> after = toDouble(density);
            const Vec3 before = testing::centroidNear(grid, blob, start);
            const Vec3 back = testing::centroidNear(grid, after, start);
            const double distance =
                std::hypot(back[0] - before[0], back[1] - before[1]) / grid.spacing[0];
            const double massChange = reference.mass(after) / reference.mass(blob) - 1.0;
            std::cout << schemeName(scheme) << " on the device, once around a 2D torus: centroid "
                      << distance << " cells from its start, mass change " << massChange << "\n";
            // MacCormack's clamp moves the centroid of so narrow a blob by a fraction of a cell,
            // walls or not (the CPU reference's too); wrapping wrong would leave it cells away.
            EXPECT_LE(distance, scheme == AdvectionScheme::SemiLagrangian ? 0.05 : 0.5)
                << schemeName(scheme);
            if (scheme == AdvectionScheme::SemiLagrangian) {
                EXPECT_NEAR(massChange, 0.0, 1e-5);
            }
        }
        expectNoValidationMessages();
    }
}

TEST_P(SmokeKernelTest, OneCellAxesMatchTheReference) {
    // One smoke cell along z: its stencils have hi == lo there, and the x- and y-faces one layer.
    for (const AdvectionScheme scheme : kAdvectionSchemes) {
        {
            SmokeSetup setup{3, 12, 1, scheme};
            setup.cellsZ = 1;
            const SmokeRun run = runSmoke(context(), setup);
            ASSERT_GT(std::count(run.mask.begin(), run.mask.end(), 1), 50);
            const double error = worstError(run, "12 x 12 x 1");
            std::cout << "3D 12 x 12 x 1 " << schemeName(scheme) << ", 3 steps: relative max error "
                      << error << "\n";
            EXPECT_LE(error, 1e-5) << schemeName(scheme);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SmokeKernelTest, NoFluidCellsGiveZeros) {
    for (const AdvectionScheme scheme : kAdvectionSchemes) {
        {
            const MacGrid basis = testing::smokeTestGrid(2, 8);
            const std::vector<std::uint8_t> mask(std::size_t(basis.cellCount()), 0);
            SmokeState state(context(), basis, 1, mask);
            EXPECT_EQ(state.fluidCellCount(), 0u);
            state.upload(std::vector<float>(mask.size(), 1.0f),
                         std::vector<float>(mask.size(), 2.0f));
            state.setEmitters(testing::smokeTestEmitters());
            const SmokeAdvectionKernels kernels(context());
            const DeviceBuffer velocity = DeviceBuffer::fromValues<float>(
                context(), std::vector<float>(std::size_t(basis.faceTotal()), 0.5f), "velocity");
            CommandSequence sequence(context());
            kernels.record(sequence, state, velocity, 0.02, scheme);
            sequence.submitAndWait();
            std::vector<float> density(mask.size(), -1.0f), temperature(mask.size(), -1.0f);
            state.download(density, temperature);
            EXPECT_EQ(*std::max_element(density.begin(), density.end()), 0.0f)
                << schemeName(scheme);
            EXPECT_EQ(*std::min_element(temperature.begin(), temperature.end()), 0.0f)
                << schemeName(scheme);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SmokeKernelTest, UploadDropsSmokeOutsideTheMask) {
    {
        const MacGrid basis = testing::smokeTestGrid(2, 8);
        const std::vector<std::uint8_t> mask = testing::ballMask(basis, 0.85);
        SmokeState state(context(), basis, 1, mask);
        std::vector<float> density(mask.size()), temperature(mask.size());
        for (std::size_t c = 0; c < mask.size(); ++c) {
            density[c] = float(c) + 1.0f;
            temperature[c] = -float(c) - 1.0f;
        }
        state.upload(density, temperature);
        std::vector<float> densityBack(mask.size()), temperatureBack(mask.size()),
            temperatureAlone(mask.size());
        state.download(densityBack, temperatureBack);
        state.temperature().download<float>(temperatureAlone);
        for (std::size_t c = 0; c < mask.size(); ++c) {
            EXPECT_EQ(densityBack[c], mask[c] ? density[c] : 0.0f) << "cell " << c;
            EXPECT_EQ(temperatureBack[c], mask[c] ? temperature[c] : 0.0f) << "cell " << c;
            EXPECT_EQ(temperatureAlone[c], temperatureBack[c]) << "cell " << c;
        }
    }
    expectNoValidationMessages();
}

TEST_P(SmokeKernelTest, AnyWorkgroupSizeGivesTheSameResult) {
    // 48 and 100 do not divide the 64² cells, so the last workgroup is partly idle.
    for (const std::uint32_t size : {1u, 48u, 100u, 256u}) {
        {
            SmokeSetup setup{2, 32, 2, AdvectionScheme::MacCormack};
            setup.workgroupSize = size;
            const SmokeRun run = runSmoke(context(), setup);
            EXPECT_LE(worstError(run, "workgroup size " + std::to_string(size)), 1e-5)
                << "workgroup size " << size;
        }
        expectNoValidationMessages();
    }
}

TEST_P(SmokeKernelTest, LargeGridsAreSplitOverSeveralDispatches) {
    // 256² = 65536 smoke cells, all fluid, with one invocation a workgroup: more groups than
    // lavapipe's maxComputeWorkGroupCount (65535), so each stage takes two dispatches there, after
    // one for the 129 x 128 x 2 velocity faces (four per invocation).
    {
        SmokeSetup setup{2, 128, 2, AdvectionScheme::MacCormack};
        setup.steps = 1;
        setup.workgroupSize = 1;
        setup.maskRadius = 2.0;
        const SmokeRun run = runSmoke(context(), setup);
        const std::uint64_t limit = context().properties().limits.maxComputeWorkGroupCount[0];
        const auto chunks = [limit](std::uint64_t n) { return (n + limit - 1) / limit; };
        EXPECT_EQ(run.dispatches, chunks(129 * 128 / 2) + 2 * chunks(65536));
        EXPECT_LE(worstError(run, "256² in chunks"), 1e-5);
    }
    expectNoValidationMessages();
}

/// The device's mass drift over 100 steps in one submission: the same as the CPU's.
TEST_P(SmokeKernelTest, MassDriftPer100StepsMatchesTheCpu) {
    for (const AdvectionScheme scheme : kAdvectionSchemes) {
        {
            // The CPU test's closed-disk set-up at 64², without emitters.
            const MacGrid basis = testing::smokeTestGrid(2, 32);
            const std::vector<std::uint8_t> mask = testing::ballMask(basis.refined(2), 0.9);
            std::vector<double> velocity = testing::unitSwirlVelocity(basis, 0.85, 11);
            roundToFloat(velocity);
            const reference::SmokeAdvection reference(basis, 2, mask);
            std::vector<double> blob =
                testing::gaussianBlob(reference.smokeGrid(), {0.2, -0.1, 0.0}, 0.1);
            for (std::size_t c = 0; c < mask.size(); ++c)
                if (!mask[c]) blob[c] = 0.0;
            roundToFloat(blob);
            std::vector<double> cpu = blob;
            for (int step = 0; step < 100; ++step)
                cpu = reference.advect(velocity, cpu, 0.02, scheme);

            const SmokeAdvectionKernels kernels(context());
            SmokeState state(context(), basis, 2, mask);
            state.upload(toFloat(blob), toFloat(blob));
            const DeviceBuffer velocityBuffer =
                DeviceBuffer::fromValues<float>(context(), toFloat(velocity), "velocity");
            CommandSequence sequence(context());
            for (int step = 0; step < 100; ++step)
                kernels.record(sequence, state, velocityBuffer, 0.02, scheme);
            sequence.submitAndWait();
            std::vector<float> density(mask.size()), temperature(mask.size());
            state.download(density, temperature);
            const double m0 = reference.mass(blob);
            const double deviceDrift = reference.mass(toDouble(density)) / m0 - 1.0;
            const double cpuDrift = reference.mass(cpu) / m0 - 1.0;
            std::cout << schemeName(scheme)
                      << ", 64² disk, 100 steps of dt 0.02, max|u| 1: mass change device "
                      << deviceDrift << ", CPU " << cpuDrift << "\n";
            EXPECT_NEAR(deviceDrift, cpuDrift, 1e-4) << schemeName(scheme);
            EXPECT_LT(std::abs(deviceDrift), 0.01) << schemeName(scheme);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SmokeKernelTest, AZeroStepGivesBackTheInputExactly) {
    for (const AdvectionScheme scheme : kAdvectionSchemes) {
        {
            SmokeSetup setup{3, 8, 2, scheme};
            setup.steps = 2;
            const SmokeRun run = runSmoke(context(), setup, 0.0);  // traces end on cell centres
            EXPECT_EQ(worstError(run, "dt 0"), 0.0) << schemeName(scheme);
        }
        expectNoValidationMessages();
    }
}

TEST_P(SmokeKernelTest, TimestampsGiveTheDurationOfEachStage) {
    for (const int dim : {2, 3})
        for (const AdvectionScheme scheme : kAdvectionSchemes) {
            {
                SmokeSetup setup{dim, dim == 2 ? 64 : 16, 2, scheme};
                setup.steps = 1;
                setup.timestamps = true;
                const SmokeRun run = runSmoke(context(), setup);
                EXPECT_LE(worstError(run, "timed"), 1e-5);
                if (context().timestampValidBits() != 0) {
                    ASSERT_EQ(run.timesMs.size(), run.dispatches);
                    double total = 0.0;
                    for (const double t : run.timesMs) total += t;
                    std::cout << "smoke_advect " << dim << "D " << run.mask.size() << " cells, "
                              << schemeName(scheme) << ": " << total << " ms a step on "
                              << context().deviceName() << "\n";
                }
            }
            expectNoValidationMessages();
        }
}

TEST_P(SmokeKernelTest, BadInputsAreRefusedWithTheirNames) {
    {
        const MacGrid basis = testing::smokeTestGrid(2, 8);
        const std::vector<std::uint8_t> mask = testing::wholeMask(basis.refined(2));
        EXPECT_THROW(SmokeState(context(), basis, 2, std::vector<std::uint8_t>(10, 1)), Error);
        SmokeState state(context(), basis, 2, mask);
        EXPECT_THROW(state.upload(std::vector<float>(5), std::vector<float>(mask.size())), Error);
        EXPECT_THROW(state.setEmitters(std::vector<SmokeEmitter>(maxSmokeEmitters + 1)), Error);
        const SmokeAdvectionKernels kernels(context());
        const DeviceBuffer small(context(), 16, "tiny velocity");
        CommandSequence sequence(context());
        try {
            kernels.record(sequence, state, small, 0.1, AdvectionScheme::SemiLagrangian);
            FAIL() << "recorded with a too small velocity buffer";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("\"tiny velocity\""), std::string::npos)
                << e.what();
        }
    }
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, SmokeKernelTest, ::testing::Bool(), testing::validationName);

}  // namespace
}  // namespace modeflow
