#pragma once
/// @file FramePreview.h
/// `modeflow run --preview`: a PNG of the smoke every K frames (2D: the smoke grid as an image;
/// 3D: ray-marched on the device, or by the CPU reference renderer with `--device cpu`; particles
/// as dots over it) and a
/// contact sheet of them at the end, made from the files (so it covers a resumed run's earlier
/// frames too, and memory stays flat however many previews a run writes). The exposure is the
/// run's: the largest 99th-percentile density of the pictures so far; with fire, flames glow,
/// the largest flame so far fully.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/preview/Image.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/simulation/Particles.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::preview {
class VolumeRenderer;
}

namespace modeflow {

class FramePreview {
public:
    /// `context`: the device that ray-marches 3D pictures; null renders them on the CPU.
    FramePreview(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                 const vulkan::VulkanContext* context);
    ~FramePreview();

    /// Renders `smoke` with `particles` over it and writes it to `file`.
    void write(const std::filesystem::path& file, const SmokeFields& smoke, bool temperature,
               const Particles& particles = {});

private:
    MacGrid mGrid;
    std::vector<std::uint8_t> mMask;
    std::unique_ptr<preview::VolumeRenderer> mRenderer;
    const vulkan::VulkanContext* mContext;
    double mExposure = 0.0;  ///< the largest 99th-percentile density of the pictures so far
    double mFlame = 0.0;     ///< the largest flame of the pictures so far: full glow
};

/// The most previews a contact sheet shows (8 rows of 6).
inline constexpr std::size_t kContactSheetFrames = 48;

/// Whether frame `frame` of `frames` gets a preview when one is written every `every` frames:
/// every `every`-th and the last.
bool previewed(int frame, int frames, int every);

/// Writes the contact sheet of a run's previews: the files `pictureOf(f)` of the frames
/// f = 1 … frames that get one and exist, at most kContactSheetFrames of them evenly spaced (the
/// first and last among them), read back one at a time. Nothing when there is none.
/// @throw modeflow::Error when a preview cannot be read or the sheet cannot be written.
void writeContactSheet(const std::filesystem::path& file, int frames, int every,
                       const std::function<std::filesystem::path(int)>& pictureOf);

}  // namespace modeflow
