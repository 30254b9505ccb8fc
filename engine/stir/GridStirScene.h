#pragma once
/// @file GridStirScene.h
/// A grid scene in the stir loop: the session (StirSession) on either backend, its view
/// (StirView: the 2D box, or an orbit camera around the 3D box) and its picture (StirRenderer).

#include "engine/stir/StirRenderer.h"
#include "engine/stir/StirScene.h"
#include "engine/stir/StirView.h"

namespace modeflow::stir {

class GridStirScene final : public StirScene {
public:
    /// @throw modeflow::Error as StirSession and StirRenderer do.
    GridStirScene(const Backend& backend, const RunInputs& run, const StirSettings& settings,
                  const vulkan::VulkanContext& context);

    void press(double x, double y, VkExtent2D window) override;
    void moveTo(double x, double y, VkExtent2D window) override;
    void release() override { mSession.release(); }
    void orbit(double dx, double dy) override;
    void zoom(double notches) override;

    void reset() override { mSession.reset(); }
    void toggleIntegrator() override { mSession.toggleIntegrator(); }
    void scaleViscosity(bool up) override { mSession.scaleViscosity(up); }
    void nextBasis() override { mSession.nextBasis(); }
    void togglePaddle() override { mSession.togglePaddle(); }

    FrameStats advance(int steps, double elapsed) override {
        return mSession.advance(steps, elapsed);
    }
    void setTiming(bool on) override { mSession.setTiming(on); }
    const SimulationSettings& settings() const override { return mSession.settings(); }

    double time() const override { return mSession.simulation().time(); }
    double energy() const override { return mSession.energy(); }
    int modeCount() const override { return mSession.modeCount(); }
    std::string status() const override { return mSession.status(); }
    SmokeFields smoke() const override { return mSession.simulation().smoke(); }

    void draw(const PictureExtras& extras, VkExtent2D size, bool blueFirst) override {
        mRenderer.draw(mSession, mView, extras, size, blueFirst);
    }
    const WindowPicture& picture() const override { return mRenderer.picture(); }

private:
    std::optional<Vec3> scenePoint(double x, double y, VkExtent2D window) const {
        return mView.scenePoint(x, y, int(window.width), int(window.height));
    }

    StirSession mSession;
    StirView mView;
    StirRenderer mRenderer;
};

}  // namespace modeflow::stir
