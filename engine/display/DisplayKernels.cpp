#include "engine/display/DisplayKernels.h"

#include <array>
#include <string>

#include "engine/core/Error.h"
#include "engine/preview/Palette.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/DisplayParams.h"
#include "shaders/display_dots.spv.h"
#include "shaders/display_picture.spv.h"
#include "shaders/display_smoke_2d.spv.h"

namespace modeflow::display {
namespace {

void requireBytes(const vulkan::DeviceBuffer& buffer, VkDeviceSize bytes) {
    if (buffer.bytes() < bytes)
        throw Error("display: buffer \"" + buffer.name() + "\" holds " +
                    std::to_string(buffer.bytes()) + " bytes, the picture needs " +
                    std::to_string(bytes));
}

shaders::DisplayParams paramsFor(const DisplayTarget& target, int sourceWidth, int sourceHeight,
                                 const PaddleOverlay& paddle) {
    shaders::DisplayParams p{};
    p.width = std::uint32_t(target.width);
    p.height = std::uint32_t(target.height);
    p.viewX = std::uint32_t(target.viewport.x);
    p.viewY = std::uint32_t(target.viewport.y);
    p.viewWidth = std::uint32_t(target.viewport.width);
    p.viewHeight = std::uint32_t(target.viewport.height);
    p.sourceWidth = std::uint32_t(sourceWidth);
    p.sourceHeight = std::uint32_t(sourceHeight);
    p.blueFirst = target.blueFirst ? 1u : 0u;
    p.paddle = paddle.shown ? 1u : 0u;
    p.paddleX = paddle.centre[0];
    p.paddleY = paddle.centre[1];
    p.paddleAxisX = paddle.axis[0];
    p.paddleAxisY = paddle.axis[1];
    p.paddleRadius = paddle.radius;
    return p;
}

/// Checks the overlay and output sizes of `target` and returns the group count of one
/// invocation per four pixels (shaders/Display.glsl).
std::uint32_t pixelGroups(const vulkan::ComputeKernel& kernel, const DisplayTarget& target,
                          const vulkan::DeviceBuffer& overlay, const vulkan::DeviceBuffer& pixels) {
    const VkDeviceSize count = VkDeviceSize(target.width) * VkDeviceSize(target.height);
    requireBytes(overlay, count);
    requireBytes(pixels, count * 4);
    const VkDeviceSize invocations = (count + 3) / 4;
    return std::uint32_t((invocations + kernel.workgroupSize() - 1) / kernel.workgroupSize());
}

}  // namespace

DisplayKernels::DisplayKernels(const vulkan::VulkanContext& context)
    : mSmoke2D(context,
               {"display_smoke_2d", display_smoke_2d_spv, 6, sizeof(shaders::DisplayParams)}),
      mPicture(context,
               {"display_picture", display_picture_spv, 3, sizeof(shaders::DisplayParams)}),
      mDots(context, {"display_dots", display_dots_spv, 2, sizeof(shaders::DisplayDotsParams)}) {}

void DisplayKernels::recordSmoke2D(vulkan::CommandSequence& sequence, const FieldBuffers& fields,
                                   const Smoke2DLook& look, const vulkan::DeviceBuffer& overlay,
                                   const DisplayTarget& target,
                                   const vulkan::DeviceBuffer& pixels) const {
    const MacGrid& grid = fields.smokeGrid;
    if (grid.dim != 2)
        throw Error("display: the 2D smoke picture needs a 2D smoke grid, not " +
                    std::to_string(grid.dim) + "D");
    shaders::DisplayParams p = paramsFor(target, grid.cells[0], grid.cells[1], look.paddle);
    p.densityScale = look.densityScale;
    p.hotScale = look.hotScale;
    p.flameScale = fields.flame ? look.flameScale : 0.0f;
    if (fields.flame) requireBytes(*fields.flame, VkDeviceSize(grid.cellCount()) * sizeof(float));
    const MacGrid& basis = fields.basisGrid;
    requireBytes(fields.smoke, VkDeviceSize(grid.cellCount()) * 2 * sizeof(float));
    requireBytes(fields.mask, VkDeviceSize(grid.cellCount() + 3) / 4 * 4);
    requireBytes(fields.faceVelocity, VkDeviceSize(basis.faceTotal()) * sizeof(float));
    p.arrows = look.arrows ? 1u : 0u;
    p.arrowSpacing = look.arrowSpacing;
    p.arrowScale = look.arrowScale;
    p.basisX = std::uint32_t(basis.cells[0]);
    p.basisY = std::uint32_t(basis.cells[1]);
    p.boundary = basis.boundaryBits() | basis.crossableSideBits() << 6;
    // Without flame binding 5 is never read: any buffer will do.
    const std::array<const vulkan::DeviceBuffer*, 6> buffers{
        &fields.smoke, &fields.mask,         &overlay,
        &pixels,       &fields.faceVelocity, fields.flame ? fields.flame : &fields.smoke};
    sequence.dispatch(mSmoke2D, buffers, p, pixelGroups(mSmoke2D, target, overlay, pixels));
}

void DisplayKernels::recordPicture(vulkan::CommandSequence& sequence,
                                   const vulkan::DeviceBuffer& picture, int pictureWidth,
                                   int pictureHeight, const PaddleOverlay& paddle,
                                   const vulkan::DeviceBuffer& overlay, const DisplayTarget& target,
                                   const vulkan::DeviceBuffer& pixels) const {
    requireBytes(picture, VkDeviceSize(pictureWidth) * VkDeviceSize(pictureHeight) * 4);
    const shaders::DisplayParams p = paramsFor(target, pictureWidth, pictureHeight, paddle);
    const std::array<const vulkan::DeviceBuffer*, 3> buffers{&picture, &overlay, &pixels};
    sequence.dispatch(mPicture, buffers, p, pixelGroups(mPicture, target, overlay, pixels));
}

void DisplayKernels::recordDots(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& dots,
                                std::uint32_t count, const DisplayTarget& target,
                                const vulkan::DeviceBuffer& pixels) const {
    if (count == 0) return;
    requireBytes(dots, VkDeviceSize(count) * 2 * sizeof(float));
    requireBytes(pixels, VkDeviceSize(target.width) * VkDeviceSize(target.height) * 4);
    const preview::Rgba c = preview::palette::kParticle;
    const std::uint32_t red = c[0], blue = c[2];
    shaders::DisplayDotsParams p{};
    p.count = count;
    p.width = std::uint32_t(target.width);
    p.height = std::uint32_t(target.height);
    p.colour = (target.blueFirst ? blue : red) | std::uint32_t(c[1]) << 8 |
               (target.blueFirst ? red : blue) << 16 | 0xffu << 24;
    const std::array<const vulkan::DeviceBuffer*, 2> buffers{&dots, &pixels};
    sequence.dispatch(mDots, buffers, p,
                      (count + mDots.workgroupSize() - 1) / mDots.workgroupSize());
}

}  // namespace modeflow::display
