/// @file ForceProjectionKernelTest.cpp
/// shaders/force_field.comp (ForceFieldKernel) and project_force(_sum).comp
/// (ForceProjectionKernel) against the CPU references engine/reference/ForceField and
/// ForceProjection: buoyancy and splats, projections in float32 and float16, split mode
/// buffers, the orthonormality round trip through the reconstruction kernel, and kernel times.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "engine/device/ForceField.h"
#include "engine/device/ForceProjection.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/reference/ForceField.h"
#include "engine/reference/ForceProjection.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/KernelTestSupport.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"
#include "tests/support/SyntheticBases.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using device::ForceFieldKernel;
using device::ForceProjectionKernel;
using device::ForceProjectionOptions;
using device::ModeBuffer;
using device::ReconstructionKernel;
using vulkan::CommandSequence;
using vulkan::DeviceBuffer;

const std::vector<ForceSplat>& splats() {
    static const std::vector<ForceSplat> all{{{0.2, -0.3, 0.1}, {1.5, -0.5, 2.0}, 0.3},
                                             {{-0.4, 0.1, -0.2}, {-0.7, 1.2, 0.3}, 0.5}};
    return all;
}

/// A smoke-grid temperature in [0, 1], float-rounded, and a fluid mask (cell centres in the unit
/// ball).
struct Smoke {
    std::vector<double> temperature;
    std::vector<std::uint8_t> mask;
};

Smoke randomSmoke(const BasisCache& cache, int scale, unsigned seed) {
    const MacGrid smoke = MacGrid::fromSpec(cache.grid).refined(scale);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    Smoke s;
    for (int z = 0; z < smoke.cells[2]; ++z)
        for (int y = 0; y < smoke.cells[1]; ++y)
            for (int x = 0; x < smoke.cells[0]; ++x) {
                const double cx = smoke.cellCentre(0, x), cy = smoke.cellCentre(1, y);
                const double cz = smoke.dim == 3 ? smoke.cellCentre(2, z) : 0.0;
                s.mask.push_back(cx * cx + cy * cy + cz * cz < 1.0);
                s.temperature.push_back(double(float(uniform(random))));
            }
    return s;
}

/// The mask as SmokeState uploads it: bytes, padded to whole words.
DeviceBuffer maskBuffer(const vulkan::VulkanContext& context, std::vector<std::uint8_t> mask) {
    mask.resize((mask.size() + 3) / 4 * 4, 0);
    return DeviceBuffer::fromValues<std::uint8_t>(context, mask, "fluid mask");
}

/// g on the device, from a g of NaNs (a DOF never written stays NaN).
Eigen::VectorXd forceFieldOnDevice(const vulkan::VulkanContext& context, const BasisCache& cache,
                                   int scale, double buoyancy, const Smoke& smoke, bool useMask,
                                   std::span<const ForceSplat> splatList = splats(),
                                   bool upDofsOnly = false) {
    ForceFieldKernel kernel(context, cache, scale);
    kernel.setSplats(splatList);
    const DeviceBuffer temperature =
        DeviceBuffer::fromValues<float>(context, testing::toFloat(smoke.temperature), "T");
    const DeviceBuffer mask = maskBuffer(context, smoke.mask);
    const std::vector<float> nan(cache.faces.size(), std::numeric_limits<float>::quiet_NaN());
    const DeviceBuffer g = DeviceBuffer::fromValues<float>(context, nan, "g");
    CommandSequence sequence(context);
    kernel.record(sequence, buoyancy, temperature, useMask ? &mask : nullptr, g, upDofsOnly);
    sequence.submitAndWait();
    return testing::downloadFloats(g, cache.faces.size());
}

/// f = Ψᵀ(w ∘ q) on the device; q per DOF (Density) or a whole face field (FaceField).
Eigen::VectorXd projectOnDevice(const vulkan::VulkanContext& context, const BasisCache& cache,
                                const Eigen::VectorXd& q, FaceQuantity quantity,
                                ModePrecision precision, const ForceProjectionOptions& options = {},
                                std::size_t* chunks = nullptr) {
    const ModeBuffer modes(context, cache.velocity.modes, precision);
    if (chunks) *chunks = modes.chunks().size();
    const ForceProjectionKernel kernel(context, cache, quantity, options);
    const DeviceBuffer input = DeviceBuffer::fromValues<float>(context, testing::toFloat(q), "q");
    const std::vector<float> nan(std::size_t(modes.modeCount()),
                                 std::numeric_limits<float>::quiet_NaN());
    const DeviceBuffer f = DeviceBuffer::fromValues<float>(context, nan, "f");
    CommandSequence sequence(context);
    kernel.record(sequence, modes, input, f);
    sequence.submitAndWait();
    return testing::downloadFloats(f, nan.size());
}

Eigen::VectorXd projectOnRounded(const BasisCache& cache, const Eigen::VectorXd& q,
                                 ModePrecision precision) {
    const BasisCache rounded = testing::withDeviceModes(cache, precision);
    // What the device multiplies: float32 weights and inputs.
    const Eigen::VectorXd w =
        testing::roundedToFloat(projectionWeights(cache, FaceQuantity::Density));
    return rounded.velocity.modes.transpose() * w.cwiseProduct(testing::roundedToFloat(q));
}

class ForceProjectionKernelTest : public testing::VulkanTest {};

TEST_P(ForceProjectionKernelTest, ForceFieldEqualsTheCpuReference) {
    // The periodic bases: splats reach across seams (the second splat lies past the channel's
    // start), and on the torus around a disk and the 3D torus the up axis wraps too.
    for (const BasisCache* cache :
         {&testing::disk2d(), &testing::ball3d(), &testing::periodicChannel2d(),
          &testing::torusAroundDisk2d(), &testing::torus3d()})
        for (const int scale : {1, 2, 3})
            for (const bool useMask : {false, true}) {
                const Smoke smoke = randomSmoke(*cache, scale, 3 + scale);
                const Eigen::VectorXd device =
                    forceFieldOnDevice(context(), *cache, scale, 1.7, smoke, useMask);
                ASSERT_FALSE(device.hasNaN()) << "a DOF was never written";
                const reference::BuoyancyInput input{1.7, scale, smoke.temperature,
                                                     useMask
                                                         ? std::span<const std::uint8_t>(smoke.mask)
                                                         : std::span<const std::uint8_t>()};
                const Eigen::VectorXd reference = reference::forceDensity(*cache, input, splats());
                EXPECT_LE(testing::relativeError(device, reference), 1e-5)
                    << cache->grid.dim << "D, periodic " << cache->grid.periodic[0]
                    << cache->grid.periodic[1] << cache->grid.periodic[2] << ", scale " << scale
                    << ", mask " << useMask;
            }
}

TEST_P(ForceProjectionKernelTest, BuoyancyAloneAssignsTheUpDofsAndZeroesOnlyWhenAsked) {
    // Without splats the buoyancy stage assigns g (no load of it); the other DOFs are zeroed
    // unless the caller reads the up DOFs alone, when they keep what they held (here NaN).
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d(), &testing::torus3d()})
        for (const bool upDofsOnly : {false, true}) {
            const int scale = 2;
            const Smoke smoke = randomSmoke(*cache, scale, 11);
            const Eigen::VectorXd device =
                forceFieldOnDevice(context(), *cache, scale, 1.3, smoke, false, {}, upDofsOnly);
            const reference::BuoyancyInput input{1.3, scale, smoke.temperature, {}};
            const Eigen::VectorXd reference = reference::forceDensity(*cache, input, {});
            const MacGrid grid = MacGrid::fromSpec(cache->grid);
            int up = 0;
            for (std::size_t d = 0; d < cache->faces.size(); ++d) {
                const bool isUp = locateFace(grid, cache->faces[d]).axis == upAxis(grid);
                up += isUp ? 1 : 0;
                if (isUp || !upDofsOnly)
                    ASSERT_NEAR(device[Eigen::Index(d)], reference[Eigen::Index(d)],
                                1e-6 * (1.0 + std::abs(reference[Eigen::Index(d)])))
                        << "DOF " << d << ", up only " << upDofsOnly;
                else
                    ASSERT_TRUE(std::isnan(device[Eigen::Index(d)]))
                        << "DOF " << d << " of another component was written";
            }
            EXPECT_GT(up, 0);
        }
}

TEST_P(ForceProjectionKernelTest, ProjectionEqualsTheCpuReference) {
    const BasisCache synthetic = testing::syntheticBasis(testing::boxGrid(3, 7), 13, 4);
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d(), &synthetic}) {
        const Eigen::VectorXd g = testing::randomVector(Eigen::Index(cache->faces.size()), 5);
        const Eigen::VectorXd exact = reference::projectForce(*cache, g, FaceQuantity::Density);
        for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
            const Eigen::VectorXd device =
                projectOnDevice(context(), *cache, g, FaceQuantity::Density, precision);
            ASSERT_FALSE(device.hasNaN());
            const double error =
                testing::relativeError(device, projectOnRounded(*cache, g, precision));
            const double exactError = testing::relativeError(device, exact);
            const bool half = precision == ModePrecision::Float16;
            std::cout << cache->grid.dim << "D, " << cache->faces.size() << " DOFs, "
                      << (half ? "float16" : "float32") << ": relative error " << error
                      << " (against double modes " << exactError << ")\n";
            EXPECT_LE(error, 1e-5);
            EXPECT_LE(exactError, half ? 1e-3 : 1e-5);
        }
    }
}

TEST_P(ForceProjectionKernelTest, BlockAndWorkgroupSizesGiveTheSameProjection) {
    const BasisCache& cache = testing::ball3d();
    const Eigen::VectorXd g = testing::randomVector(Eigen::Index(cache.faces.size()), 6);
    const Eigen::VectorXd reference = projectOnRounded(cache, g, ModePrecision::Float32);
    for (const auto& [workgroup, dofs] :
         {std::pair{64u, 64u}, std::pair{64u, 1000u}, std::pair{48u, 100u}, std::pair{1u, 7u},
          std::pair{100u, 1u << 20}}) {
        const Eigen::VectorXd device = projectOnDevice(context(), cache, g, FaceQuantity::Density,
                                                       ModePrecision::Float32, {workgroup, dofs});
        ASSERT_FALSE(device.hasNaN()) << workgroup << ", " << dofs;
        EXPECT_LE(testing::relativeError(device, reference), 1e-5)
            << "workgroup " << workgroup << ", block " << dofs;
    }
}

TEST_P(ForceProjectionKernelTest, SplitModeBuffersGiveTheSameProjection) {
    const BasisCache& cache = testing::disk2d();
    const Eigen::VectorXd g = testing::randomVector(Eigen::Index(cache.faces.size()), 7);
    for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
        const Eigen::VectorXd whole =
            projectOnDevice(context(), cache, g, FaceQuantity::Density, precision);
        const ModeBuffer probe(context(), cache.velocity.modes, precision);
        // Room for 6 modes (chunks of 4, ModeBuffer rounds down) and for 3 (chunks of 3).
        for (const int modesPerBuffer : {6, 3}) {
            const auto limited = testing::makeLimitedContext(
                GetParam(), VkDeviceSize(probe.modeStride()) * 4 * modesPerBuffer);
            std::size_t chunks = 0;
            const Eigen::VectorXd split =
                projectOnDevice(*limited, cache, g, FaceQuantity::Density, precision, {}, &chunks);
            EXPECT_GE(chunks, 3u);
            // Each mode's sum is formed the same way whichever chunk holds it.
            EXPECT_EQ(split, whole) << modesPerBuffer << " modes per buffer";
            testing::expectNoValidationMessages(*limited);
        }
    }
}

TEST_P(ForceProjectionKernelTest, ReconstructThenProjectGivesTheStateBack) {
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d()})
        for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
            // v → face field → f in one submission, no host round trip.
            const ModeBuffer modes(context(), cache->velocity.modes, precision);
            const ReconstructionKernel reconstruct(context(), *cache);
            const ForceProjectionKernel project(context(), *cache, FaceQuantity::FaceField);
            const Eigen::VectorXd v = testing::randomVector(cache->velocity.modes.cols(), 8);
            const DeviceBuffer state = testing::stateBuffer(context(), v);
            const DeviceBuffer field = reconstruct.makeFaceField();
            const DeviceBuffer back(context(), v.size() * sizeof(float), "v back");
            CommandSequence sequence(context());
            reconstruct.record(sequence, modes, state, field);
            project.record(sequence, modes, field, back);
            sequence.submitAndWait();
            const double error =
                testing::relativeError(testing::downloadFloats(back, std::size_t(v.size())), v);
            const bool half = precision == ModePrecision::Float16;
            std::cout << cache->grid.dim << "D, " << (half ? "float16" : "float32")
                      << ": round trip relative error " << error << "\n";
            EXPECT_LE(error, half ? 2e-3 : 1e-5);
        }
}

TEST_P(ForceProjectionKernelTest, UniformBuoyancyProjectsToNearlyZero) {
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d()}) {
        const int scale = 2;
        const MacGrid smoke = MacGrid::fromSpec(cache->grid).refined(scale);
        const std::vector<float> ones(std::size_t(smoke.cellCount()), 1.0f);
        const ModeBuffer modes(context(), cache->velocity.modes);
        ForceFieldKernel field(context(), *cache, scale);
        const ForceProjectionKernel project(context(), *cache, FaceQuantity::Density);
        const DeviceBuffer temperature = DeviceBuffer::fromValues<float>(context(), ones, "T");
        const DeviceBuffer g(context(), cache->faces.size() * sizeof(float), "g");
        const DeviceBuffer f(context(), modes.modeCount() * sizeof(float), "f");
        CommandSequence sequence(context());
        field.record(sequence, 2.0, temperature, nullptr, g);
        project.record(sequence, modes, g, f);
        sequence.submitAndWait();
        // Relative to the largest term Σ_d |Ψ_k[d] w_d g_d| of the sums.
        const Eigen::VectorXd w = projectionWeights(*cache, FaceQuantity::Density);
        const Eigen::VectorXd gDevice = testing::downloadFloats(g, cache->faces.size());
        const double scaleOfTerms =
            (cache->velocity.modes.cwiseAbs().transpose() * w.cwiseProduct(gDevice).cwiseAbs())
                .maxCoeff();
        const double surviving =
            testing::downloadFloats(f, modes.modeCount()).lpNorm<Eigen::Infinity>() / scaleOfTerms;
        std::cout << cache->grid.dim
                  << "D: projected uniform buoyancy / its largest term, float32: " << surviving
                  << "\n";
        EXPECT_LE(surviving, 1e-6);
    }
}

TEST_P(ForceProjectionKernelTest, BadArgumentsAreRefused) {
    {
        const BasisCache& cache = testing::disk2d();
        ForceFieldKernel field(context(), cache, 2, 2);
        EXPECT_THROW(field.setSplats(std::vector<ForceSplat>(3)), Error);
        EXPECT_THROW(field.setSplats(std::vector<ForceSplat>{{{0, 0, 0}, {1, 0, 0}, -1.0}}), Error);
        EXPECT_THROW(ForceFieldKernel(context(), cache, 0), Error);
        const DeviceBuffer small(context(), 16, "small");
        const DeviceBuffer g(context(), cache.faces.size() * sizeof(float), "g");
        CommandSequence sequence(context());
        try {
            field.record(sequence, 1.0, small, nullptr, g);
            ADD_FAILURE() << "recorded with a too small temperature buffer";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("\"small\""), std::string::npos) << e.what();
        }
        const ForceProjectionKernel project(context(), cache, FaceQuantity::FaceField);
        const ModeBuffer modes(context(), cache.velocity.modes);
        const DeviceBuffer f(context(), modes.modeCount() * sizeof(float), "f");
        EXPECT_THROW(project.record(sequence, modes, g, f), Error);  // a DOF array is no face field
        const ModeBuffer fewer(context(), cache.velocity.modes.leftCols(5));
        const ForceProjectionKernel density(context(), cache, FaceQuantity::Density);
        EXPECT_THROW(density.record(sequence, fewer, g, f), Error);
    }
    expectNoValidationMessages();
}

TEST_P(ForceProjectionKernelTest, TheWholeChainAtNEquals100MatchesTheReference) {
    // v → face field → force field → f in one submission, 128² synthetic basis, N = 100 (its time
    // per stage: tools/bench/bench_runtime_stages).
    static const BasisCache cache = testing::syntheticBasis(testing::boxGrid(2, 128), 100, 12);
    for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
        const ModeBuffer modes(context(), cache.velocity.modes, precision);
        const ReconstructionKernel reconstruct(context(), cache);
        ForceFieldKernel field(context(), cache, 2);
        field.setSplats(splats());
        const ForceProjectionKernel project(context(), cache, FaceQuantity::Density);
        const Smoke smoke = randomSmoke(cache, 2, 1);
        const DeviceBuffer temperature =
            DeviceBuffer::fromValues<float>(context(), testing::toFloat(smoke.temperature), "T");
        const Eigen::VectorXd v = testing::randomVector(100, 2);
        const DeviceBuffer state = testing::stateBuffer(context(), v);
        const DeviceBuffer faceField = reconstruct.makeFaceField();
        const DeviceBuffer g(context(), cache.faces.size() * sizeof(float), "g");
        const DeviceBuffer f(context(), 100 * sizeof(float), "f");
        CommandSequence sequence(context());
        reconstruct.record(sequence, modes, state, faceField);
        field.record(sequence, 1.0, temperature, nullptr, g);
        project.record(sequence, modes, g, f);
        sequence.submitAndWait();
        const Eigen::VectorXd reference = projectOnRounded(
            cache, reference::forceDensity(cache, {1.0, 2, smoke.temperature, {}}, splats()),
            precision);
        EXPECT_LE(testing::relativeError(testing::downloadFloats(f, 100), reference), 1e-4);
    }
}

INSTANTIATE_TEST_SUITE_P(Vulkan, ForceProjectionKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
