#include "tools/modeflow/DeviceOption.h"

#include <algorithm>
#include <cctype>

#include "engine/core/Error.h"

namespace modeflow::cli {

std::optional<vulkan::VulkanContextOptions> parseDevice(const std::string& value) {
    if (value == "cpu") return std::nullopt;
    vulkan::VulkanContextOptions options;
    if (value == "vulkan") return options;
    const bool digits =
        !value.empty() && value.size() < 6 &&
        std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); });
    if (!digits)
        throw Error("--device " + value +
                    ": expected cpu, vulkan or a Vulkan device index (0, 1, ...)");
    options.deviceIndex = std::uint32_t(std::stoul(value));
    return options;
}

}  // namespace modeflow::cli
