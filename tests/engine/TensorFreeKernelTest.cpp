/// @file TensorFreeKernelTest.cpp
/// The tensor-free advection on the device (engine/device/TensorFreeAdvection:
/// advection_samples.comp, advection_gather.comp between the reconstruction and the projection)
/// against the CPU reference TensorFreeCoefficients on real cut-cell bases, 2D and 3D: C(a, b)
/// and advect(u, x) in float32, also with the basis split over several buffers and with the
/// basis shared with the simulation.

#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/device/ModeBuffer.h"
#include "engine/device/TensorFreeAdvection.h"
#include "engine/dynamics/TensorFreeCoefficients.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/KernelTestSupport.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/RealBases.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using device::ModeBuffer;
using device::TensorFreeAdvection;
using vulkan::CommandSequence;
using vulkan::DeviceBuffer;

enum class Operation { Apply, Advect };

/// max |device − reference| / max |reference| of the operation on random float32 vectors; the
/// reference sees the modes as the device holds them.
double deviceError(const vulkan::VulkanContext& context, const BasisCache& basis,
                   Operation operation, const ModeBuffer* shared = nullptr,
                   std::size_t* chunks = nullptr) {
    const BasisCache cache = testing::withDeviceModes(basis, ModePrecision::Float32);
    const int n = int(cache.velocity.modes.cols());
    const Eigen::VectorXd a = testing::roundedToFloat(testing::randomVector(n, 51)),
                          b = testing::roundedToFloat(testing::randomVector(n, 52));
    const TensorFreeCoefficients cpu(cache.velocity.modes, cache.quadrature);
    Eigen::VectorXd reference;
    if (operation == Operation::Apply)
        cpu.apply(a, b, reference);
    else
        cpu.advect(a, b, reference);

    const TensorFreeAdvection advection(context, basis, shared);
    const DeviceBuffer aBuffer = testing::stateBuffer(context, a, "a"),
                       bBuffer = testing::stateBuffer(context, b, "b");
    DeviceBuffer out = DeviceBuffer::fromValues<float>(
        context, std::vector<float>(std::size_t(n), std::numeric_limits<float>::quiet_NaN()),
        "out");
    CommandSequence sequence(context);
    if (operation == Operation::Apply)
        advection.recordApply(sequence, aBuffer, bBuffer, out);
    else
        advection.recordAdvect(sequence, aBuffer, bBuffer, out);
    if (chunks) *chunks = sequence.dispatchCount();
    sequence.submitAndWait();
    const Eigen::VectorXd got = testing::downloadFloats(out, std::size_t(n));
    if (got.hasNaN()) return std::numeric_limits<double>::infinity();
    return testing::relativeError(got, reference);
}

class TensorFreeKernelTest : public testing::VulkanTest {};

TEST_P(TensorFreeKernelTest, ContractionsEqualTheCpuReferenceInFloat32) {
    for (const auto& [name, cache] :
         {std::pair{"disk 32^2", &testing::disk2d()}, std::pair{"ball 12^3", &testing::ball3d()},
          std::pair{"disk 40^2, 100 modes", &testing::disk2dHundredModes()}}) {
        const double apply = deviceError(context(), *cache, Operation::Apply);
        const double advect = deviceError(context(), *cache, Operation::Advect);
        std::cout << name << ": C(a, b) relative error " << apply << ", advect " << advect << "\n";
        EXPECT_LE(apply, 1e-5) << name;
        EXPECT_LE(advect, 1e-5) << name;
    }
}

TEST_P(TensorFreeKernelTest, ASharedBasisGivesTheSameResult) {
    const BasisCache& cache = testing::ball3d();
    const ModeBuffer modes(context(), cache.velocity.modes, ModePrecision::Float32);
    const double error = deviceError(context(), cache, Operation::Apply, &modes);
    EXPECT_LE(error, 1e-5) << "relative error " << error;
    const ModeBuffer half(context(), cache.velocity.modes, ModePrecision::Float16);
    EXPECT_THROW(TensorFreeAdvection(context(), cache, &half), Error);
}

TEST_P(TensorFreeKernelTest, ABasisSplitOverBuffersGivesTheSameResult) {
    const BasisCache& cache = testing::disk2dHundredModes();
    // Room for about 16 modes per buffer: several reconstruction and projection dispatches.
    const auto limited = testing::makeLimitedContext(
        GetParam(), VkDeviceSize(cache.velocity.modes.rows()) * 4 * 16 + 4096);
    std::size_t dispatches = 0, single = 0;
    const double error = deviceError(*limited, cache, Operation::Apply, nullptr, &dispatches);
    deviceError(context(), cache, Operation::Apply, nullptr, &single);
    EXPECT_GT(dispatches, single) << "the basis was not split";
    EXPECT_LE(error, 1e-5) << "relative error " << error;
    testing::expectNoValidationMessages(*limited);
}

INSTANTIATE_TEST_SUITE_P(Vulkan, TensorFreeKernelTest, ::testing::Bool(), testing::validationName);

}  // namespace
}  // namespace modeflow
