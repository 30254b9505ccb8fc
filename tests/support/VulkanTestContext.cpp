#include "tests/support/VulkanTestContext.h"

#include "engine/core/Error.h"

namespace modeflow::testing {

std::unique_ptr<vulkan::VulkanContext> makeVulkanContext(bool validation) {
    try {
        vulkan::VulkanContextOptions options;
        options.validation = validation;
        return std::make_unique<vulkan::VulkanContext>(options);
    } catch (const Error& e) {
        ADD_FAILURE() << "no usable Vulkan device (tools/install-deps.sh installs lavapipe "
                         "(mesa-vulkan-drivers) "
                         "and the validation layers): "
                      << e.what();
        return nullptr;
    }
}

void expectNoValidationMessages(const vulkan::VulkanContext& context) {
    EXPECT_EQ(context.validationMessageCount(), 0u) << [&] {
        std::string all;
        for (const auto& m : context.validationMessages()) all += m + "\n";
        return all;
    }();
}

std::string validationName(const ::testing::TestParamInfo<bool>& info) {
    return info.param ? "Validated" : "Plain";
}

}  // namespace modeflow::testing
