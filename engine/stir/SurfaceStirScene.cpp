/// @file SurfaceStirScene.cpp

#include "engine/stir/SurfaceStirScene.h"

#include <cstdint>
#include <cstdio>
#include <vector>

#include "engine/core/SceneKeywords.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/preview/SurfaceImage.h"
#include "engine/run/Backend.h"
#include "engine/stir/StrokeSplats.h"

namespace modeflow::stir {

SurfaceStirScene::SurfaceStirScene(const Backend& backend, const RunInputs& run,
                                   const StirSettings& settings,
                                   const vulkan::VulkanContext& context)
    : mRun(run),
      mStir(settings),
      mSettings(run.settings),
      mSimulation(backend.makeSurfaceSimulator(run)),
      mView(run.cache.surface.mesh),
      mDyeScale(dyeColourScale(run.settings)),
      mPicture(context),
      mSurfacePicture(context,
                      VkDeviceSize(SurfaceView::kPictureWidth) * SurfaceView::kPictureHeight * 4,
                      "surface picture") {
    // Splat radii are fractions of the box's largest side on a grid; here of the mesh's
    // diameter (the framing sphere's).
    mSplatRadius = mStir.splatRadius * 2.0 * mView.projection().radius();
}

void SurfaceStirScene::press(double x, double y, VkExtent2D window) {
    const auto hit = mView.pick(x, y, int(window.width), int(window.height));
    if (!hit) return;  // off the mesh: nothing to stir
    mDragging = true;
    mPointer = mStrokeFrom = hit->point;
    mStrokeTime = 0.0;
}

void SurfaceStirScene::moveTo(double x, double y, VkExtent2D window) {
    // Off the mesh the stroke waits where the pointer last touched it.
    if (const auto hit = mView.pick(x, y, int(window.width), int(window.height)))
        mPointer = hit->point;
}

void SurfaceStirScene::reset() {
    mSimulation->restore(0.0, mRun.initialVelocity,
                         Eigen::VectorXd::Zero(mSimulation->dye().size()));
}

void SurfaceStirScene::toggleIntegrator() {
    mSettings.integrator = otherIntegrator(mSettings.integrator);
    mSimulation->setIntegrator(mSettings.integrator);
}

void SurfaceStirScene::scaleViscosity(bool up) {
    mSettings.fluid.viscosity = scaledViscosity(
        mSettings.fluid.viscosity, up, mRun.cache.velocity.eigenvalues.maxCoeff(), mSettings.dt);
    mSimulation->setViscosity(mSettings.fluid.viscosity);
}

FrameStats SurfaceStirScene::advance(int steps, double elapsed) {
    mStrokeTime += elapsed;
    if (steps < 1) return {};
    const std::vector<ForceSplat> splats =
        mDragging ? strokeSplats(mStrokeFrom, mPointer, mStrokeTime, mSplatRadius, mStir.force)
                  : std::vector<ForceSplat>{};
    mSimulation->setSplats(splats);
    const FrameStats stats = mSimulation->advanceSteps(steps);
    mStrokeFrom = mPointer;
    mStrokeTime = 0.0;
    return stats;
}

double SurfaceStirScene::energy() const {
    return modeflow::energy(mSimulation->velocity());
}

std::string SurfaceStirScene::status() const {
    char line[200];
    std::snprintf(line, sizeof line, "%s | viscosity %.3g | %d modes (surface) | mouse: stir",
                  std::string(sceneKeyword(mSettings.integrator)).c_str(),
                  mSettings.fluid.viscosity, modeCount());
    return line;
}

SmokeFields SurfaceStirScene::smoke() const {
    return {surfaceDyeAtVertices(mRun.cache, mSimulation->dye()), {}};
}

void SurfaceStirScene::draw(const PictureExtras& extras, VkExtent2D size, bool blueFirst) {
    const preview::Image image = preview::surfaceImage(
        mRun.cache.surface.mesh, surfaceDyeAtVertices(mRun.cache, mSimulation->dye()), mDyeScale,
        SurfaceView::kPictureWidth, SurfaceView::kPictureHeight, mView.camera());
    // Packed as the kernels read them: red in the lowest byte.
    std::vector<std::uint32_t> words(image.rgba.size() / 4);
    for (std::size_t p = 0; p < words.size(); ++p)
        words[p] = std::uint32_t(image.rgba[4 * p]) | std::uint32_t(image.rgba[4 * p + 1]) << 8 |
                   std::uint32_t(image.rgba[4 * p + 2]) << 16 | 0xff000000u;
    mSurfacePicture.upload<std::uint32_t>(words);
    const display::DisplayTarget target =
        mPicture.begin(extras, size, mView.viewport(int(size.width), int(size.height)), blueFirst);
    mPicture.kernels().recordPicture(mPicture.sequence(), mSurfacePicture,
                                     SurfaceView::kPictureWidth, SurfaceView::kPictureHeight, {},
                                     mPicture.overlay(), target, mPicture.pixels());
    mPicture.finish();
}

}  // namespace modeflow::stir
