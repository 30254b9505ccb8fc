/// @file ReconstructionKernelTest.cpp
/// shaders/reconstruct_velocity.comp (ReconstructionKernel, ModeBuffer) against the CPU
/// reference engine/reference/VelocityReconstruction: float32 and float16 modes, bases split over
/// several buffers, workgroup sizes, real and synthetic bases in 2D and 3D.

#include <cstdint>
#include <iostream>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "engine/device/HalfFloat.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/KernelTestSupport.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"
#include "tests/support/SyntheticBases.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using device::ModeBuffer;
using device::ReconstructionKernel;
using vulkan::CommandSequence;
using vulkan::DeviceBuffer;

struct Case {
    const char* name;
    BasisCache cache;
};

/// Synthetic and real bases, 2D and 3D.
const std::vector<Case>& cases() {
    static const std::vector<Case> all{
        {"synthetic 2D 20x20", testing::syntheticBasis(testing::boxGrid(2, 20), 24, 1)},
        {"synthetic 3D 7^3", testing::syntheticBasis(testing::boxGrid(3, 7), 16, 2)},
        {"disk 32^2", testing::disk2d()},
        {"ball 12^3", testing::ball3d()},
    };
    return all;
}

/// The device's face field of Σ v_i Ψ_i; every DOF face starts as NaN (a face never written
/// shows), every other face as 0 (and must stay so).
Eigen::VectorXd reconstructOnDevice(const vulkan::VulkanContext& context, const BasisCache& cache,
                                    const Eigen::VectorXd& v, ModePrecision precision,
                                    std::uint32_t workgroupSize = 64,
                                    std::size_t* chunks = nullptr) {
    const ModeBuffer modes(context, cache.velocity.modes, precision);
    if (chunks) *chunks = modes.chunks().size();
    const ReconstructionKernel kernel(context, cache, workgroupSize);
    const DeviceBuffer state = testing::stateBuffer(context, v);
    DeviceBuffer field = kernel.makeFaceField();
    std::vector<float> initial(std::size_t(kernel.grid().faceTotal()), 0.0f);
    for (const std::int64_t f : cache.faces)
        initial[std::size_t(f)] = std::numeric_limits<float>::quiet_NaN();
    field.upload<float>(initial);
    CommandSequence sequence(context);
    kernel.record(sequence, modes, state, field);
    sequence.submitAndWait();
    return testing::downloadFloats(field, initial.size());
}

/// The CPU reference on the modes as the device holds them and v rounded to float32.
Eigen::VectorXd referenceOnRounded(const BasisCache& cache, const Eigen::VectorXd& v,
                                   ModePrecision precision) {
    const std::vector<double> field = reference::reconstructFaceField(
        testing::withDeviceModes(cache, precision), testing::roundedToFloat(v));
    return Eigen::Map<const Eigen::VectorXd>(field.data(), Eigen::Index(field.size()));
}

Eigen::VectorXd exactReference(const BasisCache& cache, const Eigen::VectorXd& v) {
    const std::vector<double> field = reference::reconstructFaceField(cache, v);
    return Eigen::Map<const Eigen::VectorXd>(field.data(), Eigen::Index(field.size()));
}

class ReconstructionKernelTest : public testing::VulkanTest {};

TEST_P(ReconstructionKernelTest, Float32EqualsTheCpuReference) {
    for (const Case& c : cases()) {
        const Eigen::VectorXd v = testing::randomVector(c.cache.velocity.modes.cols(), 7);
        const Eigen::VectorXd device =
            reconstructOnDevice(context(), c.cache, v, ModePrecision::Float32);
        ASSERT_FALSE(device.hasNaN()) << c.name << ": a DOF face was never written";
        const Eigen::VectorXd reference = referenceOnRounded(c.cache, v, ModePrecision::Float32);
        for (Eigen::Index f = 0; f < device.size(); ++f)
            if (reference[f] == 0.0) {
                EXPECT_EQ(device[f], 0.0) << c.name << ": face " << f;  // not a DOF (or exactly 0)
            }
        const double error = testing::relativeError(device, reference);
        const double exactError = testing::relativeError(device, exactReference(c.cache, v));
        std::cout << c.name << ", float32: relative error " << error << " (against double modes "
                  << exactError << ")\n";
        EXPECT_LE(error, 1e-5) << c.name;
        EXPECT_LE(exactError, 1e-5) << c.name;
    }
}

TEST_P(ReconstructionKernelTest, Float16StaysWithinItsMeasuredBound) {
    for (const Case& c : cases()) {
        const Eigen::VectorXd v = testing::randomVector(c.cache.velocity.modes.cols(), 8);
        const Eigen::VectorXd device =
            reconstructOnDevice(context(), c.cache, v, ModePrecision::Float16);
        ASSERT_FALSE(device.hasNaN()) << c.name;
        // The decoding and accumulation are float32-exact; the modes' rounding is the error.
        const double decoded =
            testing::relativeError(device, referenceOnRounded(c.cache, v, ModePrecision::Float16));
        const double error = testing::relativeError(device, exactReference(c.cache, v));
        std::cout << c.name << ", float16: relative error " << error
                  << " (against the rounded modes " << decoded << ")\n";
        EXPECT_LE(decoded, 1e-5) << c.name;
        EXPECT_LE(error, 1e-3) << c.name;  // measured 2.2e-4 to 3.3e-4
    }
}

TEST_P(ReconstructionKernelTest, SplitModeBuffersGiveTheSameField) {
    for (const Case& c : cases()) {
        for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
            const Eigen::VectorXd v = testing::randomVector(c.cache.velocity.modes.cols(), 9);
            const Eigen::VectorXd whole = reconstructOnDevice(context(), c.cache, v, precision);
            // Room for a quarter of the modes per buffer (and for the face field).
            const ModeBuffer probe(context(), c.cache.velocity.modes, precision);
            const VkDeviceSize modeBytes = VkDeviceSize(probe.modeStride()) * 4;
            const VkDeviceSize limit = std::max<VkDeviceSize>(
                modeBytes * ((probe.modeCount() + 3) / 4), VkDeviceSize(whole.size()) * 4);
            const auto limited = testing::makeLimitedContext(GetParam(), limit);
            std::size_t chunks = 0;
            const Eigen::VectorXd split =
                reconstructOnDevice(*limited, c.cache, v, precision, 64, &chunks);
            std::cout << c.name << (precision == ModePrecision::Float16 ? ", float16" : ", float32")
                      << ": " << chunks << " chunks, relative difference "
                      << testing::relativeError(split, whole) << "\n";
            EXPECT_GE(chunks, 3u) << c.name;
            EXPECT_LE(testing::relativeError(split, whole), 1e-6) << c.name;
            testing::expectNoValidationMessages(*limited);
        }
    }
}

TEST_P(ReconstructionKernelTest, ChunksNotAlignedToFourModesGiveTheSameField) {
    // Three modes per buffer: chunks start at modes 3, 6, 9, ..., inside the quads of v the
    // kernel reads (ModeBuffer rounds chunks down to multiples of 4 modes only where 4 fit).
    const Case& c = cases()[0];
    for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
        const Eigen::VectorXd v = testing::randomVector(c.cache.velocity.modes.cols(), 11);
        const Eigen::VectorXd whole = reconstructOnDevice(context(), c.cache, v, precision);
        const ModeBuffer probe(context(), c.cache.velocity.modes, precision);
        const VkDeviceSize limit = VkDeviceSize(probe.modeStride()) * 4 * 3;
        ASSERT_GE(limit, VkDeviceSize(whole.size()) * 4) << "the face field must fit the limit too";
        const auto limited = testing::makeLimitedContext(GetParam(), limit);
        std::size_t chunks = 0;
        const Eigen::VectorXd split =
            reconstructOnDevice(*limited, c.cache, v, precision, 64, &chunks);
        EXPECT_EQ(chunks, (c.cache.velocity.modes.cols() + 2) / 3);
        EXPECT_LE(testing::relativeError(split, whole), 1e-6);
        testing::expectNoValidationMessages(*limited);
    }
}

TEST_P(ReconstructionKernelTest, AnyWorkgroupSizeGivesTheSameField) {
    const Case& c = cases()[1];
    const Eigen::VectorXd v = testing::randomVector(c.cache.velocity.modes.cols(), 10);
    const Eigen::VectorXd reference = referenceOnRounded(c.cache, v, ModePrecision::Float32);
    for (const std::uint32_t size : {1u, 48u, 100u, 256u}) {
        const Eigen::VectorXd device =
            reconstructOnDevice(context(), c.cache, v, ModePrecision::Float32, size);
        ASSERT_FALSE(device.hasNaN()) << "workgroup size " << size;
        EXPECT_LE(testing::relativeError(device, reference), 1e-5) << "workgroup size " << size;
    }
}

TEST_P(ReconstructionKernelTest, MismatchedBuffersAreRefused) {
    {
        const BasisCache& cache = cases()[0].cache;
        const BasisCache other = testing::syntheticBasis(testing::boxGrid(2, 8), 4, 3);
        const ReconstructionKernel kernel(context(), cache);
        const ModeBuffer otherModes(context(), other.velocity.modes);
        const ModeBuffer modes(context(), cache.velocity.modes);
        const DeviceBuffer v(context(), 4 * sizeof(float), "short v");
        const DeviceBuffer field = kernel.makeFaceField();
        const DeviceBuffer small(context(), 64, "small field");
        CommandSequence sequence(context());
        EXPECT_THROW(kernel.record(sequence, otherModes, v, field), Error);
        try {
            kernel.record(sequence, modes, v, field);
            ADD_FAILURE() << "recorded with a too short state";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("\"short v\""), std::string::npos) << e.what();
        }
        const DeviceBuffer fullV(context(), modes.paddedModeCount() * sizeof(float), "v");
        EXPECT_THROW(kernel.record(sequence, modes, fullV, small), Error);
        // v must be padded to a multiple of 4 floats (the kernel reads it as vec4s).
        const BasisCache& ball = testing::ball3d();
        const ReconstructionKernel ballKernel(context(), ball);
        const ModeBuffer ballModes(context(), ball.velocity.modes);
        const DeviceBuffer unpadded(context(), ball.velocity.modes.cols() * sizeof(float),
                                    "unpadded v");
        EXPECT_THROW(ballKernel.record(sequence, ballModes, unpadded, ballKernel.makeFaceField()),
                     Error);
        // A single mode larger than the buffer limit cannot be split.
        const auto tiny = testing::makeLimitedContext(GetParam(), 256);
        EXPECT_THROW(ModeBuffer(*tiny, cache.velocity.modes), Error);
        testing::expectNoValidationMessages(*tiny);
    }
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, ReconstructionKernelTest, ::testing::Bool(),
                         testing::validationName);

TEST(HalfFloat, RoundsToNearestEvenIncludingSubnormals) {
    using device::floatToHalf;
    using device::halfToFloat;
    EXPECT_EQ(floatToHalf(1.0f), 0x3c00);
    EXPECT_EQ(floatToHalf(-2.0f), 0xc000);
    EXPECT_EQ(floatToHalf(65504.0f), 0x7bff);
    EXPECT_EQ(floatToHalf(65520.0f), 0x7c00);                  // rounds to infinity
    EXPECT_EQ(floatToHalf(1.0f + 1.0f / 2048), 0x3c00);        // tie, to even
    EXPECT_EQ(floatToHalf(1.0f + 3.0f / 2048), 0x3c02);        // tie, to even (up)
    EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -24)), 0x0001);     // smallest subnormal
    EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -25)), 0x0000);     // tie, to even (0)
    EXPECT_EQ(floatToHalf(std::ldexp(1023.0f, -24)), 0x03ff);  // largest subnormal
    EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -14)), 0x0400);     // smallest normal
    for (int bits = 0; bits < 0x7c00; ++bits) {  // every finite half survives a round trip
        ASSERT_EQ(floatToHalf(halfToFloat(std::uint16_t(bits))), bits);
        ASSERT_EQ(floatToHalf(halfToFloat(std::uint16_t(bits | 0x8000))), bits | 0x8000);
    }
}

}  // namespace
}  // namespace modeflow
