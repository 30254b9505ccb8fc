#pragma once
/// @file ValidationLog.h
/// Counts what the Khronos validation layer reports through VK_EXT_debug_utils, so tests can
/// assert that a run produced no warnings and no errors. Messages are kept (the first few) so a
/// failing test can print them.

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace modeflow::vulkan {

class ValidationLog {
public:
    /// A create-info whose callback records into this log; chain it into VkInstanceCreateInfo's
    /// pNext too, so messages about instance creation are counted. The log must outlive the
    /// messenger (its address is the callback's user data).
    VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo();

    std::size_t warningCount() const;
    std::size_t errorCount() const;
    /// The first messages (at most kKeptMessages), "warning: …" or "error: …".
    std::vector<std::string> messages() const;

    static constexpr std::size_t kKeptMessages = 32;

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user);

    mutable std::mutex mMutex;  // the layer may call back from any thread that calls Vulkan
    std::size_t mWarnings = 0;
    std::size_t mErrors = 0;
    std::vector<std::string> mMessages;
};

}  // namespace modeflow::vulkan
