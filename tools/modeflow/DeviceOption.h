#pragma once
/// @file DeviceOption.h
/// The `--device` option of the commands that simulate (DESIGN §5): `cpu` (the double-precision
/// reference), `vulkan` (the first suitable Vulkan device: discrete, else integrated, else CPU
/// such as lavapipe) or a Vulkan device index (`vulkaninfo --summary` lists them).

#include <optional>
#include <string>

#include "engine/vulkan/VulkanContext.h"

namespace modeflow::cli {

/// nullopt for `cpu`, else the context options that pick the device.
/// @throw modeflow::Error naming the option for anything else.
std::optional<vulkan::VulkanContextOptions> parseDevice(const std::string& value);

/// The help text of --device.
inline constexpr const char* kDeviceHelp =
    "cpu (double-precision reference), vulkan (first suitable device) or a Vulkan device index";

}  // namespace modeflow::cli
