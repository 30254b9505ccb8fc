#include "engine/stir/StirRenderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/run/RunInputs.h"
#include "engine/stir/StirSession.h"
#include "engine/stir/StirView.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::stir {
namespace {

/// 3D: optical depth across the box at density 1.
constexpr float kOpticalDepth = 6.0f;
/// Flames, fixed scales as the density's (a window's frames compare): 2D, the flame shown fully
/// glowing; 3D, the glow per unit of the box's largest side at flame 1.
constexpr float kFlameShown = 2.0f;
constexpr float kFlameGlow = 4.0f;

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
    : mContext(context), mFields(context, run), mPicture(context) {
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid).refined(run.settings.smokeScale);
    if (grid.dim == 3)
        mVolume = std::make_unique<preview::VolumeRenderer>(
            context, grid, run.smokeMask, StirView::kPictureWidth, StirView::kPictureHeight);
}

void StirRenderer::draw(const StirSession& session, const StirView& view,
                        const PictureExtras& extras, VkExtent2D size, bool blueFirst) {
    const display::DisplayTarget target =
        mPicture.begin(extras, size, view.viewport(int(size.width), int(size.height)), blueFirst);
    const display::FieldBuffers fields =
        mFields.of(session.simulation(), !mVolume && extras.arrows);
    if (mVolume) {
        mVolume->record(mPicture.sequence(), fields.smoke, kOpticalDepth, 2, view.camera(),
                        fields.flame, kFlameGlow);
        mPicture.kernels().recordPicture(
            mPicture.sequence(), mVolume->pictureBuffer(), mVolume->width(), mVolume->height(),
            paddleOverlay(session, view), mPicture.overlay(), target, mPicture.pixels());
    } else {
        display::Smoke2DLook look;
        look.hotScale = session.settings().simulatesTemperature() ? 1.0f : 0.0f;
        look.flameScale = kFlameShown;
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
        mPicture.kernels().recordSmoke2D(mPicture.sequence(), fields, look, mPicture.overlay(),
                                         target, mPicture.pixels());
    }
    if (!session.settings().particles.empty()) {
        // Before *mDots is read: the upload makes the buffer, or a larger one.
        const std::uint32_t dots = uploadDots(session, view, target);
        mPicture.kernels().recordDots(mPicture.sequence(), *mDots, dots, target, mPicture.pixels());
    }
    mPicture.finish();
}

std::uint32_t StirRenderer::uploadDots(const StirSession& session, const StirView& view,
                                       const display::DisplayTarget& target) {
    const Particles particles = session.simulation().particles();
    const display::Viewport& port = target.viewport;
    const MacGrid& grid = view.grid();
    std::vector<float> dots;
    dots.reserve(2 * particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3 p{particles.position[3 * i], particles.position[3 * i + 1],
                     particles.position[3 * i + 2]};
        double x = 0.0, y = 0.0;
        if (grid.dim == 2) {
            x = (p[0] - grid.origin[0]) / grid.length(0);
            y = 1.0 - (p[1] - grid.origin[1]) / grid.length(1);
        } else {
            const auto seen = view.project(p);
            if (!seen) continue;
            x = seen->x / StirView::kPictureWidth;
            y = seen->y / StirView::kPictureHeight;
        }
        dots.push_back(float(port.x + x * port.width));
        dots.push_back(float(port.y + y * port.height));
    }
    const std::size_t bytes = std::max<std::size_t>(dots.size(), 2) * sizeof(float);
    if (!mDots || mDots->bytes() < bytes)
        mDots = std::make_unique<vulkan::DeviceBuffer>(mContext, bytes, "particle dots");
    if (!dots.empty()) mDots->upload<float>(dots);
    return std::uint32_t(dots.size() / 2);
}

}  // namespace modeflow::stir
