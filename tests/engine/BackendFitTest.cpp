/// @file BackendFitTest.cpp
/// Backend::requireFits: a run whose assembled tensor's pair sums exceed the device's texel
/// buffer limit is refused from the scene alone, before any cache is read or made; tensor-free
/// runs, runs that fit and the CPU reference pass.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/run/Backend.h"
#include "tests/support/TestScenes.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

/// A whole 64³ box with free-slip walls (closed-form bases, sparse coefficients) of n modes.
SceneSpec wholeBox(int n) {
    SceneSpec scene = testing::gridScene({64, 64, 64}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 3);
    scene.basis.velocityModes = {{1, n}};
    return scene;
}

class BackendFitTest : public testing::VulkanTest {
protected:
    /// The smallest N whose N × N float32 pair sums pass the limit, and the largest that fits
    /// (N is padded to a multiple of 8 in a row).
    int tooMany() { return int(std::sqrt(double(context().texelBufferLimit()) / 4.0)) + 8; }
    int fitting() { return int(std::sqrt(double(context().texelBufferLimit()) / 4.0)) - 8; }
};

TEST_P(BackendFitTest, PairSumsAboveTheDeviceLimitAreRefusedFromTheScene) {
    const Backend device(BackendKind::Vulkan, context());
    try {
        device.requireFits(wholeBox(tooMany()));
        FAIL() << "N = " << tooMany() << " was not refused";
    } catch (const Error& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("the pair sums of N = " + std::to_string(tooMany()) + " modes"),
                  std::string::npos)
            << text;
        EXPECT_NE(text.find("use fewer modes or --device cpu"), std::string::npos) << text;
    }
    EXPECT_NO_THROW(device.requireFits(wholeBox(fitting())));
    SceneSpec tensorFree = wholeBox(tooMany());
    tensorFree.basis.coefficients = CoefficientStorage::TensorFree;  // no pair sums
    EXPECT_NO_THROW(device.requireFits(tensorFree));
    SceneSpec sparse = wholeBox(tooMany());
    sparse.basis.wall = WallKind::NoSlip;  // eigensolved: assembled only when asked for
    EXPECT_NO_THROW(device.requireFits(sparse));
    sparse.basis.coefficients = CoefficientStorage::Sparse;
    EXPECT_THROW(device.requireFits(sparse), Error);
    const Backend cpu(BackendKind::CpuReference, context());
    EXPECT_NO_THROW(cpu.requireFits(wholeBox(tooMany())));
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, BackendFitTest, ::testing::Bool(), testing::validationName);

}  // namespace
}  // namespace modeflow
