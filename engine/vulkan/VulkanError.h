#pragma once
/// @file VulkanError.h
/// Turning a failed Vulkan call into a modeflow::Error that names the call and its VkResult, so a
/// user reading "vkCreateBuffer failed: VK_ERROR_OUT_OF_DEVICE_MEMORY" knows what to look at.

#include <string>

#include <vulkan/vulkan.h>

namespace modeflow::vulkan {

/// The enumerator's name, e.g. "VK_ERROR_DEVICE_LOST" (or "VkResult(<n>)" for unknown values).
std::string resultName(VkResult result);

/// @throw modeflow::Error "<call> failed: <VkResult name>" unless `result` is VK_SUCCESS.
void check(VkResult result, const char* call);

}  // namespace modeflow::vulkan
