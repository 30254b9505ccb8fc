#pragma once
/// @file DisplayKernels.h
/// The stir window's picture on the device: one packed pixel per window pixel, in the
/// screen's byte order, for the Screen to present. 2D scenes: the smoke drawn straight from
/// field buffers (shaders/display_smoke_2d.comp); 3D scenes: the ray-marched picture
/// (engine/preview/VolumeRenderer) scaled into the viewport (shaders/display_picture.comp).
/// Both blend the TextOverlay on top and letterbox the picture (Viewport.h).

#include "engine/core/MacGrid.h"
#include "engine/display/Viewport.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::display {

/// The fields a picture shows, in buffers on the display's device, in the layouts the device
/// simulation keeps them (device::SmokeState, device::Simulation::faceVelocityBuffer()).
struct FieldBuffers {
    const vulkan::DeviceBuffer& smoke;         ///< (density, temperature) float32 per smoke cell
    const vulkan::DeviceBuffer& mask;          ///< a byte per smoke cell, non-zero inside Ω
    const vulkan::DeviceBuffer& faceVelocity;  ///< float32 per face of the basis grid
    const MacGrid& smokeGrid;
    const MacGrid& basisGrid;
    const vulkan::DeviceBuffer* flame = nullptr;  ///< float32 per smoke cell with [fire]
};

/// What a picture is drawn into: the window size, the viewport and the byte order.
struct DisplayTarget {
    int width = 0, height = 0;
    Viewport viewport;
    bool blueFirst = false;
};

/// A capsule drawn over the picture (the stir paddle), in the picture's source units
/// (DisplayParams.h).
struct PaddleOverlay {
    bool shown = false;
    float centre[2]{};
    float axis[2]{};  ///< centre to one end of the segment
    float radius = 0.0f;
};

/// How the 2D smoke is drawn.
struct Smoke2DLook {
    float densityScale = 1.0f;  ///< the density shown fully bright
    float hotScale = 0.0f;      ///< the temperature shown fully hot (0: no tint)
    float flameScale = 0.0f;    ///< the flame shown fully glowing (0 or no flame: no glow)
    PaddleOverlay paddle;       ///< in smoke cells, y up
    /// Velocity arrows, one per square of `arrowSpacing` window pixels, `arrowScale` pixels
    /// per unit of velocity.
    bool arrows = false;
    float arrowSpacing = 32.0f;
    float arrowScale = 1.0f;
};

class DisplayKernels {
public:
    /// @throw modeflow::Error if a pipeline cannot be made.
    explicit DisplayKernels(const vulkan::VulkanContext& context);

    /// Records the picture of the 2D smoke of `fields` into `pixels`; the arrows show its face
    /// velocity.
    /// @throw modeflow::Error when the smoke grid is not 2D or a buffer is too small.
    void recordSmoke2D(vulkan::CommandSequence& sequence, const FieldBuffers& fields,
                       const Smoke2DLook& look, const vulkan::DeviceBuffer& overlay,
                       const DisplayTarget& target, const vulkan::DeviceBuffer& pixels) const;
    /// Records `picture` (pictureWidth × pictureHeight packed RGBA8 words) scaled into the
    /// viewport, with `paddle` (in picture pixels, y down) over it, into `pixels`.
    /// @throw modeflow::Error when a buffer is too small.
    void recordPicture(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& picture,
                       int pictureWidth, int pictureHeight, const PaddleOverlay& paddle,
                       const vulkan::DeviceBuffer& overlay, const DisplayTarget& target,
                       const vulkan::DeviceBuffer& pixels) const;

    /// Records `count` dots (particles; `dots` holds (x, y) window pixels per dot, y down, as
    /// float32) over the picture in `pixels`, in the particle colour (preview/Palette.h).
    /// @throw modeflow::Error when a buffer is too small.
    void recordDots(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& dots,
                    std::uint32_t count, const DisplayTarget& target,
                    const vulkan::DeviceBuffer& pixels) const;

private:
    vulkan::ComputeKernel mSmoke2D;
    vulkan::ComputeKernel mPicture;
    vulkan::ComputeKernel mDots;
};

}  // namespace modeflow::display
