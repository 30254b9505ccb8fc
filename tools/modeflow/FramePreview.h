#pragma once
/// @file FramePreview.h
/// `modeflow run --preview`: a PNG of the smoke every K frames (2D: the smoke grid as an image;
/// 3D: ray-marched on the device, or by the CPU reference renderer with `--device cpu`) and a
/// contact sheet of them at the end. The exposure is the run's: the largest 99th-percentile
/// density of the pictures so far.

#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/preview/Image.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::preview {
class VolumeRenderer;
}

namespace modeflow::cli {

class FramePreview {
public:
    /// `context`: the device that ray-marches 3D pictures; null renders them on the CPU.
    FramePreview(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                 const vulkan::VulkanContext* context);
    ~FramePreview();

    /// Renders `smoke`, writes it to `file` and keeps a copy for the contact sheet.
    void write(const std::filesystem::path& file, int frame, const SmokeFields& smoke,
               bool temperature);
    /// Writes the contact sheet of every picture written so far (nothing when there is none).
    void writeContactSheet(const std::filesystem::path& file) const;

private:
    MacGrid mGrid;
    std::vector<std::uint8_t> mMask;
    std::unique_ptr<preview::VolumeRenderer> mRenderer;
    const vulkan::VulkanContext* mContext;
    double mExposure = 0.0;  ///< the largest 99th-percentile density of the pictures so far
    std::vector<preview::Image> mPictures;
    std::vector<int> mFrames;
};

}  // namespace modeflow::cli
