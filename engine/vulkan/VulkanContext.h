#pragma once
/// @file VulkanContext.h
/// The Vulkan instance, the chosen device and its compute queue: what every buffer and kernel is
/// created from. For a window (engine/display), the context also owns the window's surface and
/// picks a device and queue that compute and present to it, so the simulation and the pictures
/// share one device.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/vulkan/DeviceSelector.h"
#include "engine/vulkan/ValidationLog.h"

namespace modeflow::vulkan {

class StagingArea;

struct VulkanContextOptions {
    /// Enable VK_LAYER_KHRONOS_validation and count its messages (see ValidationLog). Also on
    /// when the environment has MODEFLOW_VULKAN_VALIDATION=1.
    bool validation = false;
    /// Only this device (position in vkEnumeratePhysicalDevices) may be chosen.
    std::optional<std::uint32_t> deviceIndex;
    /// Only devices whose name contains this fragment (case-insensitive) may be chosen.
    std::string deviceName;
    /// Treat the device's maxStorageBufferRange as at most this many bytes (0: the device's own
    /// limit). Tests use it to exercise the paths that split large arrays on any device.
    VkDeviceSize storageBufferLimit = 0;
    /// Keep buffers in device-local memory reached through staging copies even where host-visible
    /// memory would do (always so on discrete GPUs); tests use it to exercise that path anywhere.
    bool forceStaging = false;
    /// Instance extensions a window system needs (glfwGetRequiredInstanceExtensions).
    std::vector<std::string> instanceExtensions;
    /// Set for a window: makes its surface once the instance exists. The context then owns the
    /// surface, requires a queue that presents to it and enables VK_KHR_swapchain.
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

class VulkanContext {
public:
    /// @throw modeflow::Error when the loader, the validation layer (if asked for) or a suitable
    /// device is missing, or a creation call fails; the message names the call and VkResult.
    explicit VulkanContext(const VulkanContextOptions& options = {});
    ~VulkanContext();

    // Buffers and kernels keep the device handle: the context stays where it was made.
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    /// True when MODEFLOW_VULKAN_VALIDATION is set to 1 in the environment.
    static bool validationRequestedByEnvironment();

    VkInstance instance() const { return mInstance; }
    /// The window's surface (VK_NULL_HANDLE without VulkanContextOptions::createSurface).
    VkSurfaceKHR surface() const { return mSurface; }
    VkPhysicalDevice physicalDevice() const { return mSelection.device; }
    VkDevice device() const { return mDevice; }
    VkQueue queue() const { return mQueue; }
    std::uint32_t queueFamily() const { return mSelection.queueFamily; }
    const VkPhysicalDeviceProperties& properties() const { return mProperties; }
    const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return mMemoryProperties; }
    /// Valid bits of the queue's timestamps; 0 when the queue cannot write timestamps.
    std::uint32_t timestampValidBits() const { return mTimestampValidBits; }
    /// True when DeviceBuffers live in device-local memory behind staging copies: on discrete
    /// GPUs (whose host-visible memory is system RAM across the bus) or when forced.
    bool usesStaging() const { return mUsesStaging; }
    /// Invocations per subgroup (lavapipe: the SIMD width, 8 with AVX2; NVIDIA 32; AMD 32/64).
    std::uint32_t subgroupSize() const { return mSubgroupSize; }
    /// True when shaders may use 64-bit integers (shaderInt64, enabled whenever supported).
    bool hasShaderInt64() const { return mShaderInt64; }
    /// This context, for kernels whose 64-bit loads need shaderInt64 (`user` names them).
    /// @throw modeflow::Error naming the device, `user` and `--device cpu` when it lacks it.
    const VulkanContext& requireShaderInt64(const char* user) const;
    /// True when compute shaders may use subgroupAdd and friends
    /// (GL_KHR_shader_subgroup_arithmetic).
    bool hasSubgroupArithmetic() const { return mSubgroupArithmetic; }
    /// The largest storage buffer a kernel may bind: maxStorageBufferRange, or the smaller
    /// VulkanContextOptions::storageBufferLimit.
    VkDeviceSize storageBufferLimit() const { return mStorageBufferLimit; }
    /// The largest buffer a kernel may also read as a uniform texel buffer of 16-byte texels
    /// (DeviceBuffer::texelView): storageBufferLimit(), or maxTexelBufferElements texels if less.
    VkDeviceSize texelBufferLimit() const { return mTexelBufferLimit; }

    /// The chosen device's name.
    const std::string& deviceName() const { return mSelection.name; }
    /// Which device runs and why the others were rejected, several lines.
    std::string describe() const;

    bool isValidationEnabled() const { return mValidationLog != nullptr; }
    /// Validation warnings and errors so far (0 when validation is off).
    std::size_t validationMessageCount() const;
    /// The first validation messages, for test failure output.
    std::vector<std::string> validationMessages() const;

    /// vkCmdPushDescriptorSetKHR of this device (kernels bind their buffers with it).
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet() const { return mCmdPushDescriptorSet; }

    void waitIdle() const;

    /// The buffer and commands DeviceBuffer copies through where usesStaging(), made on first
    /// use and kept until the context goes (one thread at a time, as the queue).
    StagingArea& staging() const;

private:
    /// Destroys the raw handles (device, surface, messenger, instance) made so far, newest first.
    void release() noexcept;

    // Declared in creation order; the destructor releases them in reverse.
    std::unique_ptr<ValidationLog> mValidationLog;  ///< fixed address: the messenger's user data
    VkInstance mInstance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT mMessenger = VK_NULL_HANDLE;
    VkSurfaceKHR mSurface = VK_NULL_HANDLE;
    DeviceSelection mSelection;
    VkPhysicalDeviceProperties mProperties{};
    VkPhysicalDeviceMemoryProperties mMemoryProperties{};
    std::uint32_t mTimestampValidBits = 0;
    VkDeviceSize mStorageBufferLimit = 0;
    VkDeviceSize mTexelBufferLimit = 0;
    bool mUsesStaging = false;
    bool mShaderInt64 = false;
    std::uint32_t mSubgroupSize = 1;
    bool mSubgroupArithmetic = false;
    VkDevice mDevice = VK_NULL_HANDLE;
    VkQueue mQueue = VK_NULL_HANDLE;
    PFN_vkCmdPushDescriptorSetKHR mCmdPushDescriptorSet = nullptr;
    mutable std::unique_ptr<StagingArea> mStaging;  ///< released before the device
};

}  // namespace modeflow::vulkan
