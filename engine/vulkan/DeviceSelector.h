#pragma once
/// @file DeviceSelector.h
/// Picks the physical device the runtime computes on, and says why. Preference: discrete GPU,
/// then integrated, then virtual, then CPU (Mesa lavapipe), so a machine without a GPU still
/// runs. A device index or a name fragment narrows the choice; every device that is not chosen
/// gets a reason in the report (vk-bootstrap style), so "why is it running on llvmpipe?" has an
/// answer in the log.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace modeflow::vulkan {

/// The chosen device and the report that explains the choice.
struct DeviceSelection {
    VkPhysicalDevice device = VK_NULL_HANDLE;
    std::uint32_t index = 0;  ///< position in vkEnumeratePhysicalDevices
    std::uint32_t queueFamily =
        0;  ///< a family with compute (and presentation, if required) support
    std::string name;
    std::string report;  ///< one line per device: "chosen …" or "rejected …: reason"
};

class DeviceSelector {
public:
    explicit DeviceSelector(VkInstance instance) : mInstance(instance) {}

    /// Only the device at this position of vkEnumeratePhysicalDevices may be chosen.
    DeviceSelector& requireIndex(std::uint32_t index);
    /// Only devices whose name contains this fragment (case-insensitive) may be chosen.
    DeviceSelector& requireName(std::string fragment);
    /// Devices without this device extension are rejected.
    DeviceSelector& requireExtension(std::string extension);
    /// Devices below this Vulkan version (VK_MAKE_API_VERSION) are rejected.
    DeviceSelector& requireApiVersion(std::uint32_t version);
    /// The queue family must also present to `surface` (a window's): devices where no compute
    /// family can are rejected.
    DeviceSelector& requirePresentation(VkSurfaceKHR surface);

    /// @throw modeflow::Error when no device is suitable; the message lists every device and why
    /// it was rejected (or says that the loader found none at all).
    DeviceSelection select() const;

    /// 0 discrete, 1 integrated, 2 virtual, 3 CPU, 4 other: lower is preferred.
    static int typeRank(VkPhysicalDeviceType type);
    static const char* typeName(VkPhysicalDeviceType type);

private:
    VkInstance mInstance;
    std::optional<std::uint32_t> mIndex;
    std::string mName;
    std::vector<std::string> mExtensions;
    std::uint32_t mApiVersion = VK_API_VERSION_1_0;
    VkSurfaceKHR mSurface = VK_NULL_HANDLE;
};

}  // namespace modeflow::vulkan
