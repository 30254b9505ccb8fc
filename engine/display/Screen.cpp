#include "engine/display/Screen.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::display {

void requirePictureBytes(const vulkan::DeviceBuffer& pixels, VkExtent2D extent) {
    const VkDeviceSize needed = VkDeviceSize(extent.width) * extent.height * 4;
    if (pixels.bytes() < needed)
        throw Error("display: picture buffer \"" + pixels.name() + "\" holds " +
                    std::to_string(pixels.bytes()) + " bytes, the " + std::to_string(extent.width) +
                    " × " + std::to_string(extent.height) + " picture needs " +
                    std::to_string(needed));
}

}  // namespace modeflow::display
