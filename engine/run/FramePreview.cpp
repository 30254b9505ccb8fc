#include "engine/run/FramePreview.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/preview/ContactSheet.h"
#include "engine/preview/ParticleDots.h"
#include "engine/preview/PngReader.h"
#include "engine/preview/PngWriter.h"
#include "engine/preview/SmokeImage2D.h"
#include "engine/preview/VolumeReference.h"
#include "engine/preview/VolumeRenderer.h"
#include "engine/preview/VolumeView.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow {
namespace {

constexpr int kVolumeSize = 512;
/// The glow of the largest flame per unit of the box's largest side: a ray through a tenth of
/// the box at that flame gathers 0.8, a bright flame.
constexpr double kFlameGlow = 8.0;

/// The 99th percentile of the positive densities (0 without smoke): bright enough to read as
/// smoke, whatever the scene's emission rates, without a few dense cells setting the exposure.
double densityPercentile(const std::vector<double>& density) {
    std::vector<double> positive;
    for (double d : density)
        if (d > 0.0) positive.push_back(d);
    if (positive.empty()) return 0.0;
    const auto at = positive.begin() + std::ptrdiff_t(0.99 * double(positive.size() - 1));
    std::nth_element(positive.begin(), at, positive.end());
    return *at;
}

}  // namespace

FramePreview::FramePreview(const MacGrid& smokeGrid, std::span<const std::uint8_t> fluidMask,
                           const vulkan::VulkanContext* context)
    : mGrid(smokeGrid), mMask(fluidMask.begin(), fluidMask.end()), mContext(context) {
    if (mGrid.dim == 3 && context)
        mRenderer = std::make_unique<preview::VolumeRenderer>(*context, mGrid, mMask, kVolumeSize,
                                                              kVolumeSize);
}

FramePreview::~FramePreview() = default;

void FramePreview::write(const std::filesystem::path& file, const SmokeFields& smoke,
                         bool temperature, const Particles& particles) {
    // One exposure for the whole run, raised as the smoke thickens, so that pictures of one run
    // compare (a per-picture exposure would make every frame look alike).
    mExposure = std::max(mExposure, densityPercentile(smoke.density));
    const double exposure = mExposure > 0.0 ? std::max(mExposure, 1e-6) : 1.0;
    // Flames likewise: the largest so far glows fully.
    for (const double f : smoke.flame) mFlame = std::max(mFlame, std::isfinite(f) ? f : 0.0);
    const bool glows = mFlame > 0.0;
    preview::Image picture;
    if (mGrid.dim == 2) {
        preview::Smoke2DOptions options;
        options.densityScale = exposure;
        if (glows) options.flameScale = mFlame;
        picture = preview::renderSmoke2D(
            mGrid, std::span<const double>(smoke.density),
            temperature ? std::span<const double>(smoke.temperature) : std::span<const double>(),
            smoke.flame, mMask, options);
        preview::drawParticles2D(picture, mGrid,
                                 preview::pixelsPerCell(mGrid.cells[0], options.targetWidth),
                                 particles.position);
    } else {
        const std::vector<float> density(smoke.density.begin(), smoke.density.end());
        const std::vector<float> flame =
            glows ? std::vector<float>(smoke.flame.begin(), smoke.flame.end())
                  : std::vector<float>();
        // Optical depth 6 across the box at the exposure density.
        const float scale = float(6.0 / exposure);
        const float glow = glows ? float(kFlameGlow / mFlame) : 0.0f;
        if (mRenderer) {
            const vulkan::DeviceBuffer buffer =
                vulkan::DeviceBuffer::fromValues<float>(*mContext, density, "preview density");
            const std::optional<vulkan::DeviceBuffer> flameBuffer =
                glows ? std::optional(vulkan::DeviceBuffer::fromValues<float>(*mContext, flame,
                                                                              "preview flame"))
                      : std::nullopt;
            picture = mRenderer->render(buffer, scale, flameBuffer ? &*flameBuffer : nullptr, glow);
        } else {
            picture = preview::renderVolumeReference(mGrid, density, mMask, kVolumeSize,
                                                     kVolumeSize, scale, flame, glow);
        }
        preview::drawParticles3D(picture, mGrid,
                                 preview::volumeViewParams(mGrid, kVolumeSize, kVolumeSize, scale),
                                 particles.position);
    }
    preview::writePng(file, picture);
}

bool previewed(int frame, int frames, int every) {
    return frame % every == 0 || frame == frames;
}

void writeContactSheet(const std::filesystem::path& file, int frames, int every,
                       const std::function<std::filesystem::path(int)>& pictureOf) {
    std::vector<int> written;
    for (int frame = 1; frame <= frames; ++frame)
        if (previewed(frame, frames, every) && std::filesystem::exists(pictureOf(frame)))
            written.push_back(frame);
    if (written.empty()) return;
    preview::ContactSheetOptions options;
    std::vector<preview::Image> thumbnails;
    for (const std::size_t i : preview::evenlySpaced(written.size(), kContactSheetFrames)) {
        thumbnails.push_back(
            preview::thumbnail(preview::readPng(pictureOf(written[i])), options.thumbnailWidth));
        options.labels.push_back(written[i]);
    }
    const int columns = std::min<int>(6, int(thumbnails.size()));
    preview::writePng(file, preview::contactSheet(thumbnails, columns, options));
}

}  // namespace modeflow
