#pragma once
/// @file VulkanTestContext.h
/// A Vulkan context for the engine tests, with or without the validation layer. The set-up
/// script always installs lavapipe, so a machine without any Vulkan device is a broken set-up:
/// the tests fail and say so instead of skipping.

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "engine/vulkan/VulkanContext.h"

namespace modeflow::testing {

/// The context, or nullptr after recording a failure that quotes the reason.
std::unique_ptr<vulkan::VulkanContext> makeVulkanContext(bool validation);

/// A failure listing the validation layer's messages, if `context` recorded any.
void expectNoValidationMessages(const vulkan::VulkanContext& context);

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
    void expectNoValidationMessages() const { testing::expectNoValidationMessages(*mContext); }

    void TearDown() override {
        if (mContext) expectNoValidationMessages();
    }

    vulkan::VulkanContext& context() { return *mContext; }

    std::unique_ptr<vulkan::VulkanContext> mContext;
};

/// "Plain" or "Validated", the name of a VulkanTest's parameter.
std::string validationName(const ::testing::TestParamInfo<bool>& info);

}  // namespace modeflow::testing
