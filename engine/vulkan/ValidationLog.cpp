#include "engine/vulkan/ValidationLog.h"

namespace modeflow::vulkan {

VkDebugUtilsMessengerCreateInfoEXT ValidationLog::messengerCreateInfo() {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &ValidationLog::callback;
    info.pUserData = this;
    return info;
}

std::size_t ValidationLog::warningCount() const {
    std::lock_guard lock(mMutex);
    return mWarnings;
}

std::size_t ValidationLog::errorCount() const {
    std::lock_guard lock(mMutex);
    return mErrors;
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mMutex);
    return mMessages;
}

VKAPI_ATTR VkBool32 VKAPI_CALL ValidationLog::callback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto& log = *static_cast<ValidationLog*>(user);
    const bool isError = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    std::lock_guard lock(log.mMutex);
    (isError ? log.mErrors : log.mWarnings) += 1;
    if (log.mMessages.size() < kKeptMessages)
        log.mMessages.push_back(std::string(isError ? "error: " : "warning: ") +
                                (data && data->pMessage ? data->pMessage : ""));
    return VK_FALSE;  // never abort the call: the count is what tests check
}

}  // namespace modeflow::vulkan
