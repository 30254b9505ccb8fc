#include "engine/preview/VolumeRenderer.h"

#include <algorithm>
#include <array>
// The generated header uses uint32_t without including <cstdint>.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/VolumeView.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/RenderVolumeParams.h"
#include "shaders/render_volume.spv.h"

namespace modeflow::preview {
namespace {

using vulkan::DeviceBuffer;

const MacGrid& checkedGrid(const MacGrid& grid, std::size_t maskSize, int width, int height) {
    volumeViewParams(grid, width, height, 1.0f);  // throws on a 2D grid or an empty picture
    const std::int64_t cells = grid.cellCount();
    if (cells >= (std::int64_t(1) << 32))
        throw Error("3D preview: " + std::to_string(cells) +
                    " smoke cells, at most 2^32 − 1 supported");
    if (std::int64_t(width) * height >= (std::int64_t(1) << 32))
        throw Error("3D preview: " + std::to_string(width) + " × " + std::to_string(height) +
                    " pixels, at most 2^32 − 1 supported");
    if (maskSize != 0 && maskSize != std::size_t(cells))
        throw Error("3D preview: the fluid mask has " + std::to_string(maskSize) + " bytes for " +
                    std::to_string(cells) + " smoke cells");
    return grid;
}

/// The mask as the shader reads it: 4 bytes to a 32-bit word, zero-padded to whole words.
DeviceBuffer maskBuffer(const vulkan::VulkanContext& context, std::span<const std::uint8_t> mask,
                        std::size_t cells) {
    std::vector<std::uint8_t> bytes(mask.begin(), mask.end());
    if (bytes.empty()) bytes.assign(cells, 1);
    bytes.resize((cells + 3) / 4 * 4, 0);
    return DeviceBuffer::fromValues<std::uint8_t>(context, bytes, "volume preview mask");
}

/// render_volume, with its flame glow compiled in or out.
vulkan::ComputeKernelSpec kernelSpec(std::uint32_t workgroupSize, bool flame) {
    return {"render_volume", render_volume_spv, 6, sizeof(shaders::RenderVolumeParams),
            workgroupSize,   {flame ? 1u : 0u}};
}

/// Throws unless `buffer` holds `floats` floats.
void requireFloats(const DeviceBuffer& buffer, VkDeviceSize floats, const char* what,
                   std::int64_t cells) {
    const VkDeviceSize needed = floats * sizeof(float);
    if (buffer.bytes() < needed)
        throw Error(std::string("3D preview: ") + what + " buffer \"" + buffer.name() +
                    "\" holds " + std::to_string(buffer.bytes()) + " bytes, the smoke grid's " +
                    std::to_string(cells) + " cells need " + std::to_string(needed));
}

}  // namespace

VolumeRenderer::VolumeRenderer(const vulkan::VulkanContext& context, const MacGrid& smokeGrid,
                               std::span<const std::uint8_t> fluidMask, int width, int height,
                               std::uint32_t workgroupSize)
    : mContext(context),
      mGrid(checkedGrid(smokeGrid, fluidMask.size(), width, height)),
      mWidth(width),
      mHeight(height),
      mKernel(context, kernelSpec(workgroupSize, false)),
      mMask(maskBuffer(context, fluidMask, std::size_t(smokeGrid.cellCount()))),
      mExtinction(context, VkDeviceSize(smokeGrid.cellCount()) * sizeof(float),
                  "volume preview extinction"),
      mDepth(context, VkDeviceSize(smokeGrid.cellCount()) * sizeof(float),
             "volume preview optical depth"),
      mPixels(context, VkDeviceSize(width) * VkDeviceSize(height) * sizeof(std::uint32_t),
              "volume preview picture", DeviceBuffer::Placement::HostVisible),
      mSequence(context) {}

void VolumeRenderer::record(vulkan::CommandSequence& sequence, const DeviceBuffer& density,
                            float densityScale, std::uint32_t densityStride,
                            const VolumeCamera& camera, const DeviceBuffer* flame,
                            float flameScale) const {
    const std::int64_t cells = mGrid.cellCount();
    requireFloats(density, VkDeviceSize(cells) * std::max(densityStride, 1u), "density", cells);
    shaders::RenderVolumeParams params =
        volumeViewParams(mGrid, mWidth, mHeight, densityScale, camera, std::max(densityStride, 1u));
    if (flame) {
        requireFloats(*flame, VkDeviceSize(cells), "flame", cells);
        params.flameScale = checkedFlameScale(flameScale);
        if (!mFlameKernel)
            mFlameKernel.emplace(mContext, kernelSpec(mKernel.workgroupSize(), true));
    }
    const vulkan::ComputeKernel& kernel = flame ? *mFlameKernel : mKernel;
    // Without flame binding 5 is never read: any buffer will do.
    const std::array<const DeviceBuffer*, 6> buffers{&density, &mMask,   &mExtinction,
                                                     &mDepth,  &mPixels, flame ? flame : &density};
    // Grid-stride loops in the shader: any item count fits in the largest group count.
    const auto groups = [&](std::uint32_t items) {
        const std::uint32_t size = kernel.workgroupSize();
        return std::min((items + size - 1) / size,
                        mContext.properties().limits.maxComputeWorkGroupCount[0]);
    };
    params.stage = RENDER_VOLUME_STAGE_LIGHT;
    params.itemCount = params.cellsX * params.cellsY;
    sequence.dispatch(kernel, buffers, params, groups(params.itemCount));
    params.stage = RENDER_VOLUME_STAGE_IMAGE;
    params.itemCount = params.width * params.height;
    sequence.dispatch(kernel, buffers, params, groups(params.itemCount));
}

Image VolumeRenderer::picture() const {
    std::vector<std::uint32_t> words(std::size_t(mWidth) * std::size_t(mHeight));
    mPixels.download<std::uint32_t>(words);
    return unpackImage(words, mWidth, mHeight);
}

Image VolumeRenderer::render(const DeviceBuffer& density, float densityScale,
                             const DeviceBuffer* flame, float flameScale) {
    record(mSequence, density, densityScale, 1, {}, flame, flameScale);
    mSequence.submitAndWait();
    return picture();
}

}  // namespace modeflow::preview
