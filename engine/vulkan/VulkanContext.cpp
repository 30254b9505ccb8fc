#include "engine/vulkan/VulkanContext.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "engine/core/Error.h"
#include "engine/core/LibraryLeaks.h"
#include "engine/vulkan/StagingArea.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasInstanceLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

}  // namespace

bool VulkanContext::validationRequestedByEnvironment() {
    const char* value = std::getenv("MODEFLOW_VULKAN_VALIDATION");
    return value && std::strcmp(value, "1") == 0;
}

VulkanContext::VulkanContext(const VulkanContextOptions& options) {
    // The constructor owns raw handles until it returns, so a failure part way releases what
    // was made before rethrowing (the destructor does not run for a throwing constructor).
    struct Cleanup {
        VulkanContext* context;
        ~Cleanup() {
            if (context) context->release();
        }
    } cleanup{this};

    const bool validation = options.validation || validationRequestedByEnvironment();
    if (validation) {
        if (!hasInstanceLayer(kValidationLayer))
            throw Error(std::string("Vulkan validation was asked for but ") + kValidationLayer +
                        " is not installed (Debian: vulkan-validationlayers)");
        mValidationLog = std::make_unique<ValidationLog>();
    }

    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "modeflow";
    app.pEngineName = "modeflow";
    app.apiVersion = VK_API_VERSION_1_2;  // shaders target SPIR-V 1.5 (Vulkan 1.2)

    std::vector<const char*> layers, extensions;
    for (const std::string& e : options.instanceExtensions) extensions.push_back(e.c_str());
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{};
    if (validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        messengerInfo = mValidationLog->messengerCreateInfo();
    }
    VkInstanceCreateInfo instanceInfo{};
    instanceInfo.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    instanceInfo.pNext = validation ? &messengerInfo : nullptr;
    instanceInfo.pApplicationInfo = &app;
    instanceInfo.enabledLayerCount = std::uint32_t(layers.size());
    instanceInfo.ppEnabledLayerNames = layers.data();
    instanceInfo.enabledExtensionCount = std::uint32_t(extensions.size());
    instanceInfo.ppEnabledExtensionNames = extensions.data();
    VkResult created = VK_SUCCESS;
    {
        // With the validation layer the driver loads here (engine/core/LibraryLeaks.h).
        [[maybe_unused]] const IgnoreLibraryLeaks ignore;
        created = vkCreateInstance(&instanceInfo, nullptr, &mInstance);
    }
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error(
            "no Vulkan device found: vkCreateInstance failed: VK_ERROR_INCOMPATIBLE_DRIVER "
            "(no driver is installed; Debian: mesa-vulkan-drivers gives the lavapipe CPU device)");
    check(created, "vkCreateInstance");

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create)
            throw Error("vkGetInstanceProcAddr(vkCreateDebugUtilsMessengerEXT) returned null");
        check(create(mInstance, &messengerInfo, nullptr, &mMessenger),
              "vkCreateDebugUtilsMessengerEXT");
    }

    DeviceSelector selector(mInstance);
    selector.requireApiVersion(VK_API_VERSION_1_2)
        .requireExtension(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
    std::vector<const char*> deviceExtensions{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (options.createSurface) {
        mSurface = options.createSurface(mInstance);
        selector.requirePresentation(mSurface).requireExtension(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }
    if (options.deviceIndex) selector.requireIndex(*options.deviceIndex);
    if (!options.deviceName.empty()) selector.requireName(options.deviceName);
    mSelection = selector.select();
    vkGetPhysicalDeviceProperties(mSelection.device, &mProperties);
    vkGetPhysicalDeviceMemoryProperties(mSelection.device, &mMemoryProperties);
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(mSelection.device, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(mSelection.device, &familyCount, families.data());
    mTimestampValidBits = families[mSelection.queueFamily].timestampValidBits;
    mStorageBufferLimit = mProperties.limits.maxStorageBufferRange;
    mUsesStaging =
        options.forceStaging || mProperties.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
    VkPhysicalDeviceSubgroupProperties subgroup{};
    subgroup.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES;
    VkPhysicalDeviceProperties2 properties2{};
    properties2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    properties2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(mSelection.device, &properties2);
    mSubgroupSize = subgroup.subgroupSize;
    mSubgroupArithmetic = (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
                          (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT);
    if (options.storageBufferLimit > 0)
        mStorageBufferLimit = std::min(mStorageBufferLimit, options.storageBufferLimit);
    mTexelBufferLimit =
        std::min(mStorageBufferLimit, VkDeviceSize(mProperties.limits.maxTexelBufferElements) * 16);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = mSelection.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = std::uint32_t(deviceExtensions.size());
    deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
    // 64-bit integer loads let bandwidth-bound kernels move 8 bytes per load instruction, which
    // doubles their speed on lavapipe (it issues every lane's load separately).
    VkPhysicalDeviceFeatures supported{}, features{};
    vkGetPhysicalDeviceFeatures(mSelection.device, &supported);
    features.shaderInt64 = supported.shaderInt64;
    mShaderInt64 = supported.shaderInt64 == VK_TRUE;
    deviceInfo.pEnabledFeatures = &features;
    check(vkCreateDevice(mSelection.device, &deviceInfo, nullptr, &mDevice), "vkCreateDevice");
    vkGetDeviceQueue(mDevice, mSelection.queueFamily, 0, &mQueue);
    mCmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(mDevice, "vkCmdPushDescriptorSetKHR"));
    if (!mCmdPushDescriptorSet)
        throw Error("vkGetDeviceProcAddr(vkCmdPushDescriptorSetKHR) returned null");

    cleanup.context = nullptr;
}

VulkanContext::~VulkanContext() {
    release();
}

StagingArea& VulkanContext::staging() const {
    if (!mStaging) mStaging = std::make_unique<StagingArea>(*this);
    return *mStaging;
}

void VulkanContext::release() noexcept {
    if (mDevice) {
        vkDeviceWaitIdle(mDevice);
        mStaging.reset();
        vkDestroyDevice(mDevice, nullptr);
        mDevice = VK_NULL_HANDLE;
    }
    if (mSurface) {
        vkDestroySurfaceKHR(mInstance, mSurface, nullptr);
        mSurface = VK_NULL_HANDLE;
    }
    if (mMessenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(mInstance, mMessenger, nullptr);
        mMessenger = VK_NULL_HANDLE;
    }
    if (mInstance) {
        vkDestroyInstance(mInstance, nullptr);
        mInstance = VK_NULL_HANDLE;
    }
}

std::string VulkanContext::describe() const {
    std::ostringstream out;
    out << "Vulkan device: " << mSelection.name << " ("
        << DeviceSelector::typeName(mProperties.deviceType) << ", Vulkan "
        << VK_API_VERSION_MAJOR(mProperties.apiVersion) << "."
        << VK_API_VERSION_MINOR(mProperties.apiVersion) << "."
        << VK_API_VERSION_PATCH(mProperties.apiVersion) << ", queue family "
        << mSelection.queueFamily << ", "
        << (mUsesStaging ? "device-local buffers with staging" : "mapped buffers")
        << ", validation " << (isValidationEnabled() ? "on" : "off") << ")\n"
        << mSelection.report;
    return out.str();
}

std::size_t VulkanContext::validationMessageCount() const {
    return mValidationLog ? mValidationLog->warningCount() + mValidationLog->errorCount() : 0;
}

std::vector<std::string> VulkanContext::validationMessages() const {
    return mValidationLog ? mValidationLog->messages() : std::vector<std::string>{};
}

const VulkanContext& VulkanContext::requireShaderInt64(const char* user) const {
    if (!mShaderInt64)
        throw Error("Vulkan device " + deviceName() +
                    " lacks 64-bit integers in shaders (shaderInt64), which " + user +
                    " needs; run with --device cpu");
    return *this;
}

void VulkanContext::waitIdle() const {
    check(vkDeviceWaitIdle(mDevice), "vkDeviceWaitIdle");
}

}  // namespace modeflow::vulkan
