/// @file ModalApplyKernelTest.cpp
/// shaders/modal_apply.comp against the CPU reference DenseCoefficients::apply.

#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/kernels/ModalApply.h"
#include "tests/engine/RandomCoefficients.h"
#include "tests/engine/VulkanTestContext.h"

namespace modeflow {
namespace {

using vulkan::CommandSequence;
using vulkan::DeviceBuffer;
using vulkan::ModalApply;

/// Values rounded to float32, so the reference sees exactly what the device sees and the
/// comparison measures the device's float32 accumulation alone.
std::vector<float> toFloat(const Eigen::VectorXd& v) { return std::vector<float>(v.begin(), v.end()); }
Eigen::VectorXd roundedToFloat(const Eigen::VectorXd& v) { return v.cast<float>().cast<double>(); }

struct ModalApplyRun {
    Eigen::VectorXd device;     ///< the kernel's result
    Eigen::VectorXd reference;  ///< DenseCoefficients::apply on the float-rounded inputs
    std::vector<double> timesMs;
};

ModalApplyRun runModalApply(const vulkan::VulkanContext& context, int n, std::uint32_t workgroupSize,
                            bool timestamps) {
    const DenseCoefficients random = testing::randomDense(n, 1000 + n);
    const std::vector<float> packed = ModalApply::packCoefficients(random.packed());
    const DenseCoefficients rounded(n, std::vector<double>(packed.begin(), packed.end()));
    const Eigen::VectorXd a = roundedToFloat(testing::randomVector(n, 7)),
                          b = roundedToFloat(testing::randomVector(n, 8));

    ModalApplyRun run;
    rounded.apply(a, b, run.reference);

    const ModalApply kernel(context, workgroupSize);
    const DeviceBuffer packedBuffer = DeviceBuffer::fromValues<float>(context, packed, "coefficients");
    const DeviceBuffer aBuffer = DeviceBuffer::fromValues<float>(context, toFloat(a), "a");
    const DeviceBuffer bBuffer = DeviceBuffer::fromValues<float>(context, toFloat(b), "b");
    // NaN first: an output the kernel never writes shows up as a failure, not as a stale value.
    const std::vector<float> nan(n, std::numeric_limits<float>::quiet_NaN());
    DeviceBuffer out = DeviceBuffer::fromValues<float>(context, nan, "out");

    CommandSequence sequence(context, timestamps);
    kernel.record(sequence, std::uint32_t(n), packedBuffer, aBuffer, bBuffer, out);
    sequence.submitAndWait();
    run.timesMs = sequence.dispatchTimesMs();

    std::vector<float> result(n);
    out.download<float>(result);
    run.device = Eigen::Map<const Eigen::VectorXf>(result.data(), n).cast<double>();
    return run;
}

/// max_k |device − reference| / max_k |reference|.
double relativeError(const ModalApplyRun& run) {
    return (run.device - run.reference).lpNorm<Eigen::Infinity>() / run.reference.lpNorm<Eigen::Infinity>();
}

class ModalApplyKernelTest : public testing::VulkanTest {};

TEST_P(ModalApplyKernelTest, EqualsDenseCoefficientsApplyInFloat32) {
    for (const int n : {20, 64, 150}) {
        {
            const ModalApplyRun run = runModalApply(context(), n, 64, false);
            ASSERT_FALSE(run.device.hasNaN()) << "N = " << n << ": an output was never written";
            const double error = relativeError(run);
            std::cout << "N = " << n << ": relative error " << error << "\n";
            EXPECT_LE(error, 1e-5) << "N = " << n;
        }
        expectNoValidationMessages();
    }
}

TEST_P(ModalApplyKernelTest, AnyWorkgroupSizeGivesTheSameResult) {
    // 48 and 100 are not powers of two (the reduction must not assume one); 1 is the degenerate case.
    for (const std::uint32_t size : {1u, 48u, 100u, 128u}) {
        {
            const ModalApplyRun run = runModalApply(context(), 64, size, false);
            ASSERT_FALSE(run.device.hasNaN()) << "workgroup size " << size;
            EXPECT_LE(relativeError(run), 1e-5) << "workgroup size " << size;
        }
        expectNoValidationMessages();
    }
}

TEST_P(ModalApplyKernelTest, TimestampsGiveOneDurationPerDispatch) {
    {
        const ModalApplyRun run = runModalApply(context(), 150, 64, true);
        if (context().timestampValidBits() == 0) {
            EXPECT_TRUE(run.timesMs.empty());
        } else {
            ASSERT_EQ(run.timesMs.size(), 1u);
            EXPECT_GE(run.timesMs[0], 0.0);
            std::cout << "modal_apply N = 150: " << run.timesMs[0] << " ms on " << context().deviceName()
                      << "\n";
        }
        EXPECT_LE(relativeError(run), 1e-5);
    }
    expectNoValidationMessages();
}

TEST_P(ModalApplyKernelTest, SequenceChainsDispatchesWithBarriers) {
    // out1 = C(a, b), then out2 = C(out1, b) in the same submission: the second dispatch must see
    // the first one's writes.
    const int n = 20;
    {
        const DenseCoefficients random = testing::randomDense(n, 5);
        const std::vector<float> packed = ModalApply::packCoefficients(random.packed());
        const DenseCoefficients rounded(n, std::vector<double>(packed.begin(), packed.end()));
        const Eigen::VectorXd a = roundedToFloat(testing::randomVector(n, 1)),
                              b = roundedToFloat(testing::randomVector(n, 2));

        const ModalApply kernel(context());
        const DeviceBuffer c = DeviceBuffer::fromValues<float>(context(), packed, "coefficients");
        const DeviceBuffer aBuffer = DeviceBuffer::fromValues<float>(context(), toFloat(a), "a");
        const DeviceBuffer bBuffer = DeviceBuffer::fromValues<float>(context(), toFloat(b), "b");
        const DeviceBuffer out1(context(), n * sizeof(float), "out1"), out2(context(), n * sizeof(float), "out2");
        CommandSequence sequence(context(), true);
        kernel.record(sequence, n, c, aBuffer, bBuffer, out1);
        kernel.record(sequence, n, c, out1, bBuffer, out2);
        sequence.submitAndWait();
        EXPECT_EQ(sequence.dispatchCount(), 2u);
        if (sequence.isTiming()) {
            EXPECT_EQ(sequence.dispatchTimesMs().size(), 2u);
        }

        std::vector<float> first(n), second(n);
        out1.download<float>(first);
        out2.download<float>(second);
        Eigen::VectorXd firstReference, secondReference;
        rounded.apply(a, b, firstReference);
        const Eigen::VectorXd firstDevice = Eigen::Map<const Eigen::VectorXf>(first.data(), n).cast<double>();
        rounded.apply(firstDevice, b, secondReference);
        const Eigen::VectorXd secondDevice = Eigen::Map<const Eigen::VectorXf>(second.data(), n).cast<double>();
        EXPECT_LE((firstDevice - firstReference).lpNorm<Eigen::Infinity>() /
                      firstReference.lpNorm<Eigen::Infinity>(), 1e-5);
        EXPECT_LE((secondDevice - secondReference).lpNorm<Eigen::Infinity>() /
                      secondReference.lpNorm<Eigen::Infinity>(), 1e-5);

        // The sequence can be recorded and submitted again.
        kernel.record(sequence, n, c, aBuffer, bBuffer, out2);
        sequence.submitAndWait();
        out2.download<float>(second);
        EXPECT_EQ(second, first);
        EXPECT_THROW(sequence.submitAndWait(), Error);  // nothing recorded
    }
    expectNoValidationMessages();
}

TEST_P(ModalApplyKernelTest, TooSmallBuffersAreRefused) {
    {
        const ModalApply kernel(context());
        const DeviceBuffer small(context(), 10 * sizeof(float), "small");
        const DeviceBuffer vector(context(), 20 * sizeof(float), "vector");
        CommandSequence sequence(context());
        try {
            kernel.record(sequence, 20, small, vector, vector, vector);
            FAIL() << "recorded with a too small coefficient buffer";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("\"small\""), std::string::npos) << e.what();
        }
    }
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, ModalApplyKernelTest, ::testing::Bool(), testing::validationName);

}  // namespace
}  // namespace modeflow
