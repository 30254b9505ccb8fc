#pragma once
/// @file VolumeRenderer.h
/// The 3D preview on the device (shaders/render_volume.comp; CPU reference and the look:
/// VolumeReference.h, camera: VolumeView.h): a light pass over the grid's columns, then one
/// ray-marched invocation per pixel writing packed RGBA8, in one submission. The renderer owns
/// its fluid mask, scratch fields and picture buffer; the density stays the caller's buffer
/// (e.g. SmokeState::density()), read as one float per smoke cell, so nothing is copied.

#include <cstdint>
#include <optional>
#include <span>

#include "engine/core/MacGrid.h"
#include "engine/preview/Image.h"
#include "engine/preview/VolumeView.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::preview {

class VolumeRenderer {
public:
    /// A renderer of width × height pictures of fields on the 3D `smokeGrid`; `fluidMask` has
    /// one byte per smoke cell, non-zero inside Ω (empty: all fluid).
    /// @throw modeflow::Error when the grid is not 3D or has 2^32 cells or more, the mask has the
    ///        wrong size, the picture size is not positive, or a buffer exceeds the device's
    ///        storage buffer range.
    VolumeRenderer(const vulkan::VulkanContext& context, const MacGrid& smokeGrid,
                   std::span<const std::uint8_t> fluidMask, int width, int height,
                   std::uint32_t workgroupSize = 64);

    /// Renders `density` (at least one float per smoke cell) with `densityScale`, the optical
    /// depth across the box's largest side at density 1: records both passes, submits, waits and
    /// reads the picture back. `flame` (one float per smoke cell; null: none) glows with
    /// `flameScale` (RenderVolumeParams.h).
    /// @throw modeflow::Error when a buffer is too small, a scale is negative or not finite, or
    ///        the submission fails.
    Image render(const vulkan::DeviceBuffer& density, float densityScale,
                 const vulkan::DeviceBuffer* flame = nullptr, float flameScale = 0.0f);

    /// Records both passes into `sequence` (to share a submission with a simulation step, after
    /// the step's dispatches); picture() reads the result once the sequence was submitted.
    /// `densityStride`: floats from one cell's density to the next (2 reads the density of
    /// SmokeState::fields() in place); `flame` as in render() (e.g. SmokeState::second(Fuel)).
    void record(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& density,
                float densityScale, std::uint32_t densityStride = 1,
                const VolumeCamera& camera = {}, const vulkan::DeviceBuffer* flame = nullptr,
                float flameScale = 0.0f) const;
    /// The picture of the last submitted record(). After the submission's fence only.
    Image picture() const;
    /// The picture on the device: width × height packed RGBA8 words (red in the low byte), rows
    /// from the top, for kernels that draw it further (the stir window).
    const vulkan::DeviceBuffer& pictureBuffer() const { return mPixels; }

    int width() const { return mWidth; }
    int height() const { return mHeight; }

private:
    const vulkan::VulkanContext& mContext;
    MacGrid mGrid;
    int mWidth;
    int mHeight;
    vulkan::ComputeKernel mKernel;
    /// render_volume's flame variant, made when a picture first glows.
    mutable std::optional<vulkan::ComputeKernel> mFlameKernel;
    vulkan::DeviceBuffer mMask;
    vulkan::DeviceBuffer mExtinction;
    vulkan::DeviceBuffer mDepth;
    vulkan::DeviceBuffer mPixels;
    vulkan::CommandSequence mSequence;
};

}  // namespace modeflow::preview
