#pragma once
/// @file StirRenderer.h
/// The stir window's picture, drawn on the display's device into a buffer of packed pixels that
/// a Screen presents: a 2D scene's smoke straight from the field buffers (DisplayKernels), a 3D
/// scene ray-marched from the view's camera (VolumeRenderer) and scaled into the window; the
/// paddle, the velocity arrows, the particles and the text (statistics, key help) over it, in a
/// WindowPicture.

#include <cstdint>
#include <memory>

#include <vulkan/vulkan.h>

#include "engine/preview/VolumeRenderer.h"
#include "engine/stir/DisplayedFields.h"
#include "engine/stir/WindowPicture.h"

namespace modeflow::stir {

class StirSession;
class StirView;

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

    /// The last picture (valid after a draw()).
    const WindowPicture& picture() const { return mPicture; }

private:
    /// The particles' places in the window (2D: the smoke grid's box in the viewport, y up; 3D:
    /// the camera's picture scaled into it), uploaded as dots; their count.
    std::uint32_t uploadDots(const StirSession& session, const StirView& view,
                             const display::DisplayTarget& target);

    const vulkan::VulkanContext& mContext;
    std::unique_ptr<vulkan::DeviceBuffer> mDots;
    DisplayedFields mFields;
    WindowPicture mPicture;
    std::unique_ptr<preview::VolumeRenderer> mVolume;  ///< 3D scenes
};

}  // namespace modeflow::stir
