#pragma once
/// @file VulkanTestContext.h
/// A Vulkan context for the engine tests, with or without the validation layer. The set-up
/// script always installs lavapipe, so a machine without any Vulkan device is a broken set-up:
/// the tests fail and say so instead of skipping.

#include <memory>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::testing {

/// The context, or nullptr after recording a failure that quotes the reason.
inline std::unique_ptr<vulkan::VulkanContext> makeVulkanContext(bool validation) {
    try {
        vulkan::VulkanContextOptions options;
        options.validation = validation;
        return std::make_unique<vulkan::VulkanContext>(options);
    } catch (const Error& e) {
        ADD_FAILURE() << "no usable Vulkan device (tools/install-deps.sh installs lavapipe (mesa-vulkan-drivers) "
                         "and the validation layers): "
                      << e.what();
        return nullptr;
    }
}

/// Base fixture, parameterized on validation: each test runs once without and once with the
/// Khronos validation layer, and the validated run must end with zero warnings and errors.
class VulkanTest : public ::testing::TestWithParam<bool> {
protected:
    void SetUp() override {
        mContext = makeVulkanContext(GetParam());
        ASSERT_NE(mContext, nullptr);
        ASSERT_EQ(mContext->isValidationEnabled(),
                  GetParam() || vulkan::VulkanContext::validationRequestedByEnvironment());
    }

    /// Called by each test after its Vulkan objects are gone (messages can come on destruction).
    void expectNoValidationMessages() const {
        EXPECT_EQ(mContext->validationMessageCount(), 0u) << [this] {
            std::string all;
            for (const auto& m : mContext->validationMessages()) all += m + "\n";
            return all;
        }();
    }

    void TearDown() override {
        if (mContext) expectNoValidationMessages();
    }

    vulkan::VulkanContext& context() { return *mContext; }

    std::unique_ptr<vulkan::VulkanContext> mContext;
};

inline std::string validationName(const ::testing::TestParamInfo<bool>& info) {
    return info.param ? "Validated" : "Plain";
}

}  // namespace modeflow::testing
