/// @file ModalContractionKernelTest.cpp
/// DeviceCoefficients::recordApply (shaders/modal_pair_sums*.comp + modal_combine.comp) against
/// the CPU reference StructuralCoefficients::apply: dense, sparse, and dense split into chunks;
/// and recordAdvect (modal_pair_weights, modal_advect_*.comp) against
/// StructuralCoefficients::advect.

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModalKernels.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "shaders/ModalStepParams.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using testing::roundedDense;
using testing::roundedToFloat;

using device::DeviceCoefficients;
using device::ModalKernels;
using vulkan::CommandSequence;
using vulkan::DeviceBuffer;

/// The vector in float32, zero-padded as the kernels read it.
std::vector<float> toFloat(const Eigen::VectorXd& v) {
    std::vector<float> values(device::paddedSize(int(v.size())), 0.0f);
    std::copy(v.begin(), v.end(), values.begin());
    return values;
}

/// max_k |device − reference| / max_k |reference| for out = C(a, b), a and b random.
double contractionError(const vulkan::VulkanContext& context, const StructuralCoefficients& c,
                        std::size_t* chunks = nullptr, std::vector<double>* timesMs = nullptr) {
    const int n = c.size();
    const Eigen::VectorXd a = roundedToFloat(testing::randomVector(n, 7)),
                          b = roundedToFloat(testing::randomVector(n, 8));
    Eigen::VectorXd reference;
    c.apply(a, b, reference);

    const ModalKernels kernels(context);
    const DeviceCoefficients device(context, c);
    if (chunks) *chunks = device.chunkCount();
    const DeviceBuffer aBuffer = DeviceBuffer::fromValues<float>(context, toFloat(a), "a");
    const DeviceBuffer bBuffer = DeviceBuffer::fromValues<float>(context, toFloat(b), "b");
    // NaN first: an output the kernels never write shows up as a failure, not as a stale value.
    const std::vector<float> nan(n, std::numeric_limits<float>::quiet_NaN());
    DeviceBuffer out = DeviceBuffer::fromValues<float>(context, nan, "out");
    CommandSequence sequence(context, timesMs != nullptr);
    device.recordApply(sequence, kernels, aBuffer, bBuffer, out);
    sequence.submitAndWait();
    if (timesMs) *timesMs = sequence.dispatchTimesMs();

    std::vector<float> result(n);
    out.download<float>(result);
    const Eigen::VectorXd got = Eigen::Map<const Eigen::VectorXf>(result.data(), n).cast<double>();
    if (got.hasNaN()) return std::numeric_limits<double>::infinity();
    return (got - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

/// The same for advect(u, x) (MHD's induction term).
double advectionError(const vulkan::VulkanContext& context, const StructuralCoefficients& c) {
    const int n = c.size();
    const Eigen::VectorXd u = roundedToFloat(testing::randomVector(n, 17)),
                          x = roundedToFloat(testing::randomVector(n, 18));
    Eigen::VectorXd reference;
    c.advect(u, x, reference);
    const ModalKernels kernels(context);
    const DeviceCoefficients device(context, c, nullptr, nullptr, true);
    const DeviceBuffer uBuffer = DeviceBuffer::fromValues<float>(context, toFloat(u), "u");
    const DeviceBuffer xBuffer = DeviceBuffer::fromValues<float>(context, toFloat(x), "x");
    const std::vector<float> nan(n, std::numeric_limits<float>::quiet_NaN());
    DeviceBuffer out = DeviceBuffer::fromValues<float>(context, nan, "out");
    CommandSequence sequence(context);
    device.recordAdvect(sequence, kernels, uBuffer, xBuffer, out);
    sequence.submitAndWait();
    std::vector<float> result(n);
    out.download<float>(result);
    const Eigen::VectorXd got = Eigen::Map<const Eigen::VectorXf>(result.data(), n).cast<double>();
    if (got.hasNaN()) return std::numeric_limits<double>::infinity();
    return (got - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

class ModalContractionKernelTest : public testing::VulkanTest {};

TEST_P(ModalContractionKernelTest, AdvectionEqualsCpuAdvectInFloat32) {
    for (const int n : {2, 20, 150}) {
        const double dense =
            advectionError(context(), roundedDense(testing::randomDense(n, 2000 + n)));
        const SparseCoefficients sparse =
            SparseCoefficients::fromDense(roundedDense(testing::randomDense(n, 2100 + n, 0.1)));
        const double sparseError = advectionError(context(), sparse);
        std::cout << "advect N = " << n << ": dense relative error " << dense << ", sparse "
                  << sparseError << "\n";
        EXPECT_LE(dense, 1e-5) << "dense, N = " << n;
        EXPECT_LE(sparseError, 1e-5) << "sparse, N = " << n;
    }
    const DeviceCoefficients withoutAdvection(context(), roundedDense(testing::randomDense(8, 3)));
    EXPECT_THROW(withoutAdvection.advectGroups(), Error);
}

TEST_P(ModalContractionKernelTest, DenseEqualsCpuApplyInFloat32) {
    for (const int n : {2, 20, 64, 150}) {
        const double error =
            contractionError(context(), roundedDense(testing::randomDense(n, 1000 + n)));
        std::cout << "dense N = " << n << ": relative error " << error << "\n";
        EXPECT_LE(error, 1e-5) << "N = " << n;
    }
}

TEST_P(ModalContractionKernelTest, SparseEqualsCpuApplyInFloat32) {
    for (const int n : {20, 90}) {
        const SparseCoefficients sparse =
            SparseCoefficients::fromDense(roundedDense(testing::randomDense(n, 300 + n, 0.1)));
        const double error = contractionError(context(), sparse);
        std::cout << "sparse N = " << n << " (" << sparse.nonZeros() << " entries): relative error "
                  << error << "\n";
        EXPECT_LE(error, 1e-5) << "N = " << n;
    }
}

TEST_P(ModalContractionKernelTest, ManyModesEqualCpuApplyAcrossTheCombinesTiles) {
    // The combine cuts the N x N pair sums into tiles of 64 texel columns (256 modes) by sets of
    // up to 64 rows: N past one tile, and one past a whole number of sets and tiles, with two
    // random float32 entries a pair (a dense N^3 array of this size would not fit).
    for (const int n : {257, 601}) {
        std::mt19937_64 random{std::uint64_t(n)};
        std::uniform_int_distribution<int> mode(0, n - 1);
        std::uniform_real_distribution<double> value(-1.0, 1.0);
        std::vector<CoefficientEntry> entries;
        for (int k = 0; k < n; ++k)
            for (int j = k + 1; j < n; ++j) {
                const int first = mode(random), second = (first + 1 + mode(random) % (n - 1)) % n;
                for (const int i : {first, second})
                    entries.push_back({k, i, j, double(float(value(random)))});
            }
        const SparseCoefficients sparse(n, std::move(entries));
        const double error = contractionError(context(), sparse);
        std::cout << "sparse N = " << n << " (" << sparse.nonZeros() << " entries): relative error "
                  << error << "\n";
        EXPECT_LE(error, 1e-5) << "N = " << n;
    }
}

TEST_P(ModalContractionKernelTest, UpdatePipelinesAreMadeOncePerVariant) {
    // modal_update.comp's operation and flags are specialization constants: one pipeline each,
    // made when first recorded and kept.
    const ModalKernels kernels(context());
    const vulkan::ComputeKernel& begin = kernels.update(MODAL_OP_BEGIN, false, false);
    EXPECT_EQ(&begin, &kernels.update(MODAL_OP_BEGIN, false, false));
    EXPECT_NE(&begin, &kernels.update(MODAL_OP_MIDPOINT, false, false));
    EXPECT_NE(&kernels.update(MODAL_OP_MIDPOINT, true, false),
              &kernels.update(MODAL_OP_MIDPOINT, false, false));
    EXPECT_NE(&kernels.update(MODAL_OP_MIDPOINT, false, true),
              &kernels.update(MODAL_OP_MIDPOINT, false, false));
}

TEST(ModalContractionSplit, ChunksAboveTheStorageLimitGiveTheSameResult) {
    // 64 modes: 2016 pairs of 256 bytes, in tiles of 64 pairs (16 kB). A 100 kB limit splits them
    // into 6 chunks.
    vulkan::VulkanContextOptions options;
    options.storageBufferLimit = 100'000;
    options.validation = true;
    std::unique_ptr<vulkan::VulkanContext> context;
    ASSERT_NO_THROW(context = std::make_unique<vulkan::VulkanContext>(options));
    {
        std::size_t chunks = 0;
        const double error =
            contractionError(*context, roundedDense(testing::randomDense(64, 9)), &chunks);
        EXPECT_EQ(chunks, 6u);
        EXPECT_LE(error, 1e-5);
        const double advection =
            advectionError(*context, roundedDense(testing::randomDense(64, 10)));
        EXPECT_LE(advection, 1e-5) << "advect over 6 chunks";
    }
    EXPECT_EQ(context->validationMessageCount(), 0u);
}

TEST(ModalContractionSplit, PairSumsAboveTheTexelLimitAreRefusedClearly) {
    // The combine reads the N x N pair sums as texels: 64 modes need 16 kB of them.
    vulkan::VulkanContextOptions options;
    options.storageBufferLimit = 10'000;
    const vulkan::VulkanContext context(options);
    const SparseCoefficients sparse =
        SparseCoefficients::fromDense(roundedDense(testing::randomDense(64, 11, 0.1)));
    try {
        const DeviceCoefficients device(context, sparse);
        ADD_FAILURE() << "16 kB of pair sums under a 10 kB limit were accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("pair sums of N = 64 modes"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("--device cpu"), std::string::npos) << e.what();
    }
}

TEST_P(ModalContractionKernelTest, TimestampsGiveOneDurationPerDispatch) {
    std::vector<double> times;
    EXPECT_LE(
        contractionError(context(), roundedDense(testing::randomDense(150, 4)), nullptr, &times),
        1e-5);
    if (context().timestampValidBits() == 0) {
        EXPECT_TRUE(times.empty());
    } else {
        ASSERT_EQ(times.size(), 3u);  // pair sums, combine by rows, by columns
        std::cout << "N = 150 on " << context().deviceName() << ": pair sums " << times[0]
                  << " ms, combine " << times[1] + times[2] << " ms\n";
    }
}

TEST_P(ModalContractionKernelTest, TimingCanBeSwitchedOffBetweenSubmissions) {
    // Windows time a sample of their steps: timestamps cost lavapipe about a dispatch each.
    const DenseCoefficients c = roundedDense(testing::randomDense(40, 5));
    const ModalKernels kernels(context());
    const DeviceCoefficients device(context(), c);
    const DeviceBuffer a =
        DeviceBuffer::fromValues<float>(context(), toFloat(testing::randomVector(40, 1)), "a");
    DeviceBuffer out(context(), 40 * sizeof(float), "out");
    CommandSequence sequence(context(), true);
    if (!sequence.isTiming()) GTEST_SKIP() << "the queue writes no timestamps";
    for (const bool timed : {false, true, false}) {
        sequence.setTiming(timed);
        EXPECT_EQ(sequence.isTiming(), timed);
        device.recordApply(sequence, kernels, a, a, out);
        EXPECT_THROW(sequence.setTiming(!timed), Error);  // not while recording
        sequence.submitAndWait();
        EXPECT_EQ(sequence.dispatchTimesMs().size(), timed ? 3u : 0u);
    }
    expectNoValidationMessages();
}

TEST_P(ModalContractionKernelTest, TexelBindingOfABufferWithoutTexelsIsRefusedClearly) {
    // The pair sums read the coefficients and `a` as texels (binding 0 and 1): a buffer smaller
    // than one 16-byte texel has no texel view, and binding it must say so, not read zeros.
    const ModalKernels kernels(context());
    const DeviceBuffer tiny(context(), 12, "tiny coefficients");
    const DeviceBuffer a(context(), 32, "a"), sums(context(), 64, "sums");
    EXPECT_EQ(tiny.texelView(), VK_NULL_HANDLE);
    ASSERT_NE(a.texelView(), VK_NULL_HANDLE);
    CommandSequence sequence(context());
    const std::array<const DeviceBuffer*, 3> buffers{&tiny, &a, &sums};
    try {
        sequence.dispatch(kernels.pairSums, buffers, shaders::PairSumsParams{1, 0, 1, 0}, 1);
        FAIL() << "a buffer without a texel view was bound as texels";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("tiny coefficients"), std::string::npos) << message;
        EXPECT_NE(message.find("texel"), std::string::npos) << message;
        EXPECT_NE(message.find("binding 0"), std::string::npos) << message;
    }
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(PlainAndValidated, ModalContractionKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
