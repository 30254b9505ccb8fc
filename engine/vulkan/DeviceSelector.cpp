#include "engine/vulkan/DeviceSelector.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

#include "engine/core/Error.h"
#include "engine/core/LibraryLeaks.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

std::string versionString(std::uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
           "." + std::to_string(VK_API_VERSION_PATCH(v));
}

struct Candidate {
    VkPhysicalDevice device;
    std::uint32_t index;
    VkPhysicalDeviceProperties properties;
    std::optional<std::uint32_t> queueFamily;
    std::string rejection;  ///< empty while suitable
};

}  // namespace

DeviceSelector& DeviceSelector::requireIndex(std::uint32_t index) {
    mIndex = index;
    return *this;
}

DeviceSelector& DeviceSelector::requireName(std::string fragment) {
    mName = std::move(fragment);
    return *this;
}

DeviceSelector& DeviceSelector::requireExtension(std::string extension) {
    mExtensions.push_back(std::move(extension));
    return *this;
}

DeviceSelector& DeviceSelector::requireApiVersion(std::uint32_t version) {
    mApiVersion = version;
    return *this;
}

DeviceSelector& DeviceSelector::requirePresentation(VkSurfaceKHR surface) {
    mSurface = surface;
    return *this;
}

int DeviceSelector::typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 3;
        default:
            return 4;
    }
}

const char* DeviceSelector::typeName(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return "CPU";
        default:
            return "other";
    }
}

DeviceSelection DeviceSelector::select() const {
    std::uint32_t count = 0;
    {
        // The first call loads the driver (engine/core/LibraryLeaks.h).
        [[maybe_unused]] const IgnoreLibraryLeaks ignore;
        check(vkEnumeratePhysicalDevices(mInstance, &count, nullptr), "vkEnumeratePhysicalDevices");
    }
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(mInstance, &count, devices.data()),
          "vkEnumeratePhysicalDevices");
    if (count == 0)
        throw Error(
            "no Vulkan device found: the loader reports no physical device (install "
            "mesa-vulkan-drivers for the lavapipe CPU device, or a GPU driver)");

    std::vector<Candidate> candidates;
    for (std::uint32_t index = 0; index < count; ++index) {
        Candidate c{devices[index], index, {}, std::nullopt, {}};
        vkGetPhysicalDeviceProperties(c.device, &c.properties);

        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(c.device, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(c.device, &familyCount, families.data());
        // A compute-only family, where there is one, runs beside graphics work on real GPUs.
        for (std::uint32_t f = 0; f < familyCount; ++f) {
            if (!(families[f].queueFlags & VK_QUEUE_COMPUTE_BIT)) continue;
            if (mSurface) {
                // The window's pictures are computed and presented on one queue.
                VkBool32 presents = VK_FALSE;
                vkGetPhysicalDeviceSurfaceSupportKHR(c.device, f, mSurface, &presents);
                if (!presents) continue;
            }
            const bool computeOnly = !(families[f].queueFlags & VK_QUEUE_GRAPHICS_BIT);
            if (!c.queueFamily || computeOnly) c.queueFamily = f;
            if (computeOnly) break;
        }

        std::uint32_t extensionCount = 0;
        vkEnumerateDeviceExtensionProperties(c.device, nullptr, &extensionCount, nullptr);
        std::vector<VkExtensionProperties> extensions(extensionCount);
        vkEnumerateDeviceExtensionProperties(c.device, nullptr, &extensionCount, extensions.data());
        std::set<std::string> available;
        for (const auto& e : extensions) available.insert(e.extensionName);

        if (mIndex && *mIndex != index)
            c.rejection = "not the requested device index " + std::to_string(*mIndex);
        else if (!mName.empty() &&
                 lower(c.properties.deviceName).find(lower(mName)) == std::string::npos)
            c.rejection = "name does not contain \"" + mName + "\"";
        else if (c.properties.apiVersion < mApiVersion)
            c.rejection = "Vulkan " + versionString(c.properties.apiVersion) +
                          " is below the required " + versionString(mApiVersion);
        else if (!c.queueFamily)
            c.rejection = mSurface ? "no queue family that computes and presents to the window"
                                   : "no queue family with compute support";
        else
            for (const auto& e : mExtensions)
                if (!available.count(e)) {
                    c.rejection = "lacks the device extension " + e;
                    break;
                }
        candidates.push_back(c);
    }

    const Candidate* best = nullptr;
    for (const auto& c : candidates)
        if (c.rejection.empty() &&
            (!best || typeRank(c.properties.deviceType) < typeRank(best->properties.deviceType)))
            best = &c;
    int suitable = 0;
    for (const auto& c : candidates) suitable += c.rejection.empty();

    std::ostringstream report;
    for (const auto& c : candidates) {
        const bool chosen = &c == best;
        report << (chosen ? "chosen   " : "rejected ") << "#" << c.index << " "
               << c.properties.deviceName << " (" << typeName(c.properties.deviceType)
               << ", Vulkan " << versionString(c.properties.apiVersion) << ")";
        if (chosen)
            report << ": "
                   << (suitable == 1
                           ? "the only suitable device"
                           : "most preferred type (discrete > integrated > virtual > CPU)");
        else if (!c.rejection.empty())
            report << ": " << c.rejection;
        else
            report << ": a more preferred device type is available";
        report << "\n";
    }
    if (!best) throw Error("no suitable Vulkan device:\n" + report.str());
    return {best->device, best->index, *best->queueFamily, best->properties.deviceName,
            report.str()};
}

}  // namespace modeflow::vulkan
