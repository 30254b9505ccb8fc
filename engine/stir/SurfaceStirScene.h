#pragma once
/// @file SurfaceStirScene.h
/// A surface scene in the stir loop, on the chosen backend: the flow and its dye
/// (SurfaceSimulator), an orbit camera (SurfaceView), and the user's hand: a left
/// drag over the mesh stirs with force splats along the pointer's path on the surface, as a
/// grid's drag does (StrokeSplats.h), each turned into the surface's tangent planes and
/// projected on the velocity basis (SurfaceForce.h). The picture is drawn on the CPU
/// (preview::surfaceImage) and scaled into the window by the display kernels. Surfaces have no
/// shaped bases and no paddle: those keys do nothing.

#include <memory>
#include <optional>

#include "engine/run/RunInputs.h"
#include "engine/simulation/SurfaceSimulator.h"
#include "engine/stir/StirScene.h"
#include "engine/stir/SurfaceView.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::stir {

class SurfaceStirScene final : public StirScene {
public:
    /// Starts the prepared surface run on `backend` at its initial state with no dye; `backend`,
    /// `run` and `context` must outlive the scene.
    /// @throw modeflow::Error as Backend::makeSurfaceSimulator.
    SurfaceStirScene(const Backend& backend, const RunInputs& run, const StirSettings& settings,
                     const vulkan::VulkanContext& context);

    void press(double x, double y, VkExtent2D window) override;
    void moveTo(double x, double y, VkExtent2D window) override;
    void release() override { mDragging = false; }
    void orbit(double dx, double dy) override { mView.orbit(dx, dy); }
    void zoom(double notches) override { mView.zoom(notches); }

    void reset() override;
    void toggleIntegrator() override;
    void scaleViscosity(bool up) override;
    void nextBasis() override {}
    void togglePaddle() override {}

    FrameStats advance(int steps, double elapsed) override;
    void setTiming(bool) override {}  // a surface step is not timed by stage
    const SimulationSettings& settings() const override { return mSettings; }

    double time() const override { return mSimulation->time(); }
    double energy() const override;
    int modeCount() const override { return int(mRun.initialVelocity.size()); }
    std::string status() const override;
    SmokeFields smoke() const override;

    void draw(const PictureExtras& extras, VkExtent2D size, bool blueFirst) override;
    const WindowPicture& picture() const override { return mPicture; }

    const SurfaceView& view() const { return mView; }

private:
    const RunInputs& mRun;
    StirSettings mStir;
    SimulationSettings mSettings;  ///< the run's, with the user's integrator and viscosity
    std::unique_ptr<SurfaceSimulator> mSimulation;
    SurfaceView mView;
    double mSplatRadius = 0.0;
    double mDyeScale = 1.0;

    bool mDragging = false;
    Vec3 mPointer{};     ///< on the surface, where the pointer last touched it
    Vec3 mStrokeFrom{};  ///< at the last step
    double mStrokeTime = 0.0;

    WindowPicture mPicture;
    vulkan::DeviceBuffer mSurfacePicture;  ///< the CPU's picture, RGBA words
};

}  // namespace modeflow::stir
