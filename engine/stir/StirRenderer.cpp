#include "engine/stir/StirRenderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/Error.h"
#include "engine/pipeline/RunInputs.h"
#include "engine/preview/PngWriter.h"
#include "engine/stir/StirKeys.h"
#include "engine/stir/StirSession.h"
#include "engine/stir/StirView.h"

namespace modeflow::stir {
namespace {

/// 3D: optical depth across the box at density 1.
constexpr float kOpticalDepth = 6.0f;

std::vector<display::TextBlock> overlayText(const PictureExtras& extras, int scale) {
    std::vector<display::TextBlock> blocks;
    if (!extras.statistics.empty()) blocks.push_back({8, 8, extras.statistics, false});
    if (extras.help) {
        // Bottom right, clear of the statistics: actions flush right, keys in a column before.
        const HelpColumns help = helpColumns();
        const int margin = 8 * scale;
        blocks.push_back({-margin, -margin, help.actions, true});
        blocks.push_back({-(margin + display::textWidth(help.actions, scale) + 6 * scale), -margin,
                          help.keys, true});
    }
    return blocks;
}

/// The paddle in the picture's source units, when paddle mode is on.
display::PaddleOverlay paddleOverlay(const StirSession& session, const StirView& view) {
    display::PaddleOverlay overlay;
    const auto paddle = session.paddle();
    if (!paddle) return overlay;
    const MacGrid& grid = view.grid();
    if (grid.dim == 2) {
        // Smoke cells, y up.
        for (int a = 0; a < 2; ++a) {
            overlay.centre[a] = float((paddle->centre[a] - grid.origin[a]) / grid.spacing[a]);
            overlay.axis[a] = float(paddle->axis[a] / grid.spacing[a]);
        }
        overlay.radius = float(paddle->radius / grid.spacing[0]);
        overlay.shown = true;
        return overlay;
    }
    // Picture pixels, y down: the capsule's segment projected, its radius at the centre's depth.
    Vec3 end{};
    for (int a = 0; a < 3; ++a) end[a] = paddle->centre[a] + paddle->axis[a];
    const auto centre = view.project(paddle->centre), tip = view.project(end);
    if (!centre || !tip) return overlay;
    overlay.centre[0] = float(centre->x);
    overlay.centre[1] = float(centre->y);
    overlay.axis[0] = float(tip->x - centre->x);
    overlay.axis[1] = float(tip->y - centre->y);
    overlay.radius = float(paddle->radius * centre->pixelsPerLength);
    overlay.shown = true;
    return overlay;
}

}  // namespace

StirRenderer::StirRenderer(const vulkan::VulkanContext& context, const RunInputs& run)
    : mContext(context),
      mFields(context, run),
      mKernels(context),
      mOverlay(context),
      mSequence(context) {
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid).refined(run.settings.smokeScale);
    if (grid.dim == 3)
        mVolume = std::make_unique<preview::VolumeRenderer>(
            context, grid, run.smokeMask, StirView::kPictureWidth, StirView::kPictureHeight);
}

void StirRenderer::draw(const StirSession& session, const StirView& view,
                        const PictureExtras& extras, VkExtent2D size, bool blueFirst) {
    if (!mPixels || size.width != mExtent.width || size.height != mExtent.height) {
        mPixels = std::make_unique<vulkan::DeviceBuffer>(
            mContext, VkDeviceSize(size.width) * size.height * 4, "window picture");
        mExtent = size;
    }
    mBlueFirst = blueFirst;
    const int width = int(size.width), height = int(size.height);
    const int scale = height >= 600 ? 2 : 1;
    mOverlay.update(width, height, overlayText(extras, scale), scale);
    const display::DisplayTarget target{width, height, view.viewport(width, height), blueFirst};
    const display::FieldBuffers fields =
        mFields.of(session.simulation(), !mVolume && extras.arrows);
    if (mVolume) {
        mVolume->record(mSequence, fields.smoke, kOpticalDepth, 2, view.camera());
        mKernels.recordPicture(mSequence, mVolume->pictureBuffer(), mVolume->width(),
                               mVolume->height(), paddleOverlay(session, view), mOverlay.buffer(),
                               target, *mPixels);
    } else {
        display::Smoke2DLook look;
        look.hotScale = session.settings().simulatesTemperature() ? 1.0f : 0.0f;
        look.paddle = paddleOverlay(session, view);
        look.arrows = extras.arrows;
        if (extras.arrows) {
            // The RMS speed over the box, ½|v|² = ½∫|u|², spans half an arrow square.
            const MacGrid& grid = view.grid();
            const double area = grid.spacing[0] * grid.cells[0] * grid.spacing[1] * grid.cells[1];
            const double rms = std::sqrt(2.0 * extras.energy / area);
            look.arrowSpacing = float(std::max(16, target.viewport.width / 24));
            look.arrowScale = float(0.5 * look.arrowSpacing / std::max(rms, 1e-6));
        }
        mKernels.recordSmoke2D(mSequence, fields, look, mOverlay.buffer(), target, *mPixels);
    }
    mSequence.submitAndWait();
}

preview::Image StirRenderer::picture() const {
    const int width = int(mExtent.width), height = int(mExtent.height);
    std::vector<std::uint32_t> words(std::size_t(width) * std::size_t(height));
    mPixels->download<std::uint32_t>(words);
    return preview::unpackImage(words, width, height, mBlueFirst);
}

void StirRenderer::saveScreenshot(const std::filesystem::path& file) const {
    if (!mPixels) throw Error("no frame was drawn, so there is no screenshot for " + file.string());
    preview::writePng(file, picture());
}

}  // namespace modeflow::stir
