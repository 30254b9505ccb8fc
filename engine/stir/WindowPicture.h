#pragma once
/// @file WindowPicture.h
/// The stir window's picture whatever draws it (StirRenderer for grids, SurfaceRenderer for
/// surfaces): a buffer of packed pixels on the display's device at the screen's size, the text
/// over it (statistics, key help), the display kernels and a command sequence to record them in,
/// and the last picture read back for screenshots.

#include <filesystem>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "engine/display/DisplayKernels.h"
#include "engine/display/TextOverlay.h"
#include "engine/preview/Image.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::stir {

/// What the picture shows besides the fluid.
struct PictureExtras {
    std::string statistics;  ///< lines at the top left (empty: none)
    bool help = false;       ///< the keys, bottom right
    bool arrows = false;     ///< velocity arrows (2D)
    double energy = 0.0;     ///< ½|v|², which sets the arrows' scale
};

/// Refuses a picture of width × height pixels larger than one storage buffer of `context`'s
/// device, saying how large it may be at that shape; `what` names what set the size (an option,
/// "the window").
/// @throw modeflow::Error "WHAT: a picture of W × H pixels takes B bytes, more than ...".
void requirePictureFits(const vulkan::VulkanContext& context, int width, int height,
                        const std::string& what);

class WindowPicture {
public:
    /// Draws on `context`, which must outlive it.
    /// @throw modeflow::Error when a kernel cannot be made.
    explicit WindowPicture(const vulkan::VulkanContext& context);

    /// Gets ready to record a `size` picture with `viewport` and the byte order `blueFirst`:
    /// the pixel buffer at that size and the text of `extras` over it. Returns where the kernels
    /// draw.
    display::DisplayTarget begin(const PictureExtras& extras, VkExtent2D size,
                                 const display::Viewport& viewport, bool blueFirst);
    const display::DisplayKernels& kernels() const { return mKernels; }
    vulkan::CommandSequence& sequence() { return mSequence; }
    const vulkan::DeviceBuffer& overlay() const { return mOverlay.buffer(); }
    /// Submits what was recorded since begin() and waits for it.
    void finish() { mSequence.submitAndWait(); }

    /// The last picture, for Screen::present (valid after a finish()).
    const vulkan::DeviceBuffer& pixels() const { return *mPixels; }
    /// Its size (0 × 0 before the first begin()).
    VkExtent2D extent() const { return mExtent; }
    /// The last picture in RGBA byte order.
    preview::Image picture() const;
    /// Writes the last picture as a PNG.
    /// @throw modeflow::Error when nothing was drawn yet or the file cannot be written.
    void saveScreenshot(const std::filesystem::path& file) const;

private:
    const vulkan::VulkanContext& mContext;
    display::DisplayKernels mKernels;
    display::TextOverlay mOverlay;
    vulkan::CommandSequence mSequence;
    std::unique_ptr<vulkan::DeviceBuffer> mPixels;
    VkExtent2D mExtent{};
    bool mBlueFirst = false;
};

}  // namespace modeflow::stir
