#pragma once
/// @file StirRenderer.h
/// The stir window's picture, drawn on the display's device into a buffer of packed pixels that
/// a Screen presents: a 2D scene's smoke straight from the field buffers (DisplayKernels), a 3D
/// scene ray-marched from the view's camera (VolumeRenderer) and scaled into the window; the
/// paddle, the velocity arrows and the text (statistics, key help) over it. Screenshots are the
/// drawn picture, whatever the screen.

#include <filesystem>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "engine/display/DisplayKernels.h"
#include "engine/display/TextOverlay.h"
#include "engine/preview/Image.h"
#include "engine/preview/VolumeRenderer.h"
#include "engine/stir/DisplayedFields.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::stir {

class StirSession;
class StirView;

/// What the picture shows besides the smoke.
struct PictureExtras {
    std::string statistics;  ///< lines at the top left (empty: none)
    bool help = false;       ///< the keys, bottom right
    bool arrows = false;     ///< velocity arrows (2D)
    double energy = 0.0;     ///< ½|v|², which sets the arrows' scale
};

class StirRenderer {
public:
    /// Draws simulations of `run` on `context`, which must outlive the renderer, as does `run`.
    /// @throw modeflow::Error when a kernel or buffer cannot be made.
    StirRenderer(const vulkan::VulkanContext& context, const RunInputs& run);

    /// Draws the session's simulation as `view` shows it, with `extras`, into a `size` picture
    /// with the byte order `blueFirst`; one submission, waited for.
    /// @throw modeflow::Error when a device call fails.
    void draw(const StirSession& session, const StirView& view, const PictureExtras& extras,
              VkExtent2D size, bool blueFirst);

    /// The last picture, for Screen::present (valid after a draw()).
    const vulkan::DeviceBuffer& pixels() const { return *mPixels; }
    /// Its size (0 × 0 before the first draw()).
    VkExtent2D extent() const { return mExtent; }
    /// The last picture in RGBA byte order.
    preview::Image picture() const;
    /// Writes the last picture as a PNG.
    /// @throw modeflow::Error when nothing was drawn yet or the file cannot be written.
    void saveScreenshot(const std::filesystem::path& file) const;

private:
    const vulkan::VulkanContext& mContext;
    DisplayedFields mFields;
    display::DisplayKernels mKernels;
    display::TextOverlay mOverlay;
    vulkan::CommandSequence mSequence;
    std::unique_ptr<preview::VolumeRenderer> mVolume;  ///< 3D scenes
    std::unique_ptr<vulkan::DeviceBuffer> mPixels;
    VkExtent2D mExtent{};
    bool mBlueFirst = false;
};

}  // namespace modeflow::stir
