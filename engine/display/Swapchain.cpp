#include "engine/display/Swapchain.h"

#include <algorithm>

#include "engine/core/Error.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::display {
namespace {

bool isBlueFirst(VkFormat format) {
    return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
}

bool isEightBitRgba(VkFormat format) {
    return isBlueFirst(format) || format == VK_FORMAT_R8G8B8A8_UNORM ||
           format == VK_FORMAT_R8G8B8A8_SRGB;
}

}  // namespace

Swapchain::Swapchain(const vulkan::VulkanContext& context, VkExtent2D wanted) : mContext(context) {
    create(wanted, VK_NULL_HANDLE);
}

Swapchain::~Swapchain() {
    if (mSwapchain) vkDestroySwapchainKHR(mContext.device(), mSwapchain, nullptr);
}

void Swapchain::recreate(VkExtent2D wanted) {
    mContext.waitIdle();
    const VkSwapchainKHR old = mSwapchain;
    create(wanted, old);
    vkDestroySwapchainKHR(mContext.device(), old, nullptr);
}

void Swapchain::create(VkExtent2D wanted, VkSwapchainKHR old) {
    const VkPhysicalDevice gpu = mContext.physicalDevice();
    const VkSurfaceKHR surface = mContext.surface();
    if (!surface) throw Error("a swapchain needs a Vulkan context made with a window surface");
    VkSurfaceCapabilitiesKHR caps{};
    vulkan::check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, surface, &caps),
                  "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("the window's surface does not take transfer writes into its images");

    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, formats.data());
    // The kernels' bytes are sRGB-encoded already: any 8-bit format shows them as they are.
    const auto chosen =
        std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
            return isEightBitRgba(f.format) && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
        });
    if (chosen == formats.end())
        throw Error(
            "the window's surface offers no 8-bit RGBA or BGRA format in sRGB colour space");
    mFormat = chosen->format;
    mBlueFirst = isBlueFirst(mFormat);

    // A surface either dictates its size or lets the application pick one within limits.
    mExtent = caps.currentExtent;
    if (mExtent.width == 0xffffffffu) {
        mExtent.width =
            std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        mExtent.height =
            std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    std::uint32_t images = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) images = std::min(images, caps.maxImageCount);
    VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & alpha))
        alpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                            -caps.supportedCompositeAlpha);

    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = surface;
    info.minImageCount = images;
    info.imageFormat = mFormat;
    info.imageColorSpace = chosen->colorSpace;
    info.imageExtent = mExtent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = alpha;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    vulkan::check(vkCreateSwapchainKHR(mContext.device(), &info, nullptr, &created),
                  "vkCreateSwapchainKHR");
    mSwapchain = created;
    vkGetSwapchainImagesKHR(mContext.device(), mSwapchain, &count, nullptr);
    mImages.resize(count);
    vkGetSwapchainImagesKHR(mContext.device(), mSwapchain, &count, mImages.data());
}

}  // namespace modeflow::display
