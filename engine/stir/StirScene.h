#pragma once
/// @file StirScene.h
/// What the stir loop (StirApp) drives, whatever the scene is: the fluid with the user's hand in
/// it, the view that says where the pointer is and how the camera turns, and the picture. One
/// loop runs both kinds: a grid scene (GridStirScene: StirSession, StirView, StirRenderer, on
/// either backend) and a surface scene (SurfaceStirScene: the CPU reference only).

#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "engine/simulation/FrameStats.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/simulation/SmokeFields.h"
#include "engine/stir/StirSession.h"
#include "engine/stir/WindowPicture.h"

namespace modeflow {
class Backend;
struct RunInputs;
}  // namespace modeflow

namespace modeflow::stir {

class StirScene {
public:
    virtual ~StirScene() = default;

    /// The left button pressed, moved and released at window fractions (x right, y down) of a
    /// `window`-pixel screen: it stirs (or moves the paddle) where the view puts the pointer.
    virtual void press(double x, double y, VkExtent2D window) = 0;
    virtual void moveTo(double x, double y, VkExtent2D window) = 0;
    virtual void release() = 0;
    /// The camera (3D views): turned by a pointer motion of (dx, dy) window fractions, moved
    /// closer by positive wheel notches. A 2D view stays as it is.
    virtual void orbit(double dx, double dy) = 0;
    virtual void zoom(double notches) = 0;

    /// The keys that change the fluid (StirKeys.h); where the scene has no shaped bases or no
    /// paddle, those keys do nothing.
    virtual void reset() = 0;
    virtual void toggleIntegrator() = 0;
    virtual void scaleViscosity(bool up) = 0;
    virtual void nextBasis() = 0;
    virtual void togglePaddle() = 0;

    /// `steps` steps with the pointer's motion since the last call spread over them; `elapsed`:
    /// the window clock's seconds since the last call (the pointer's speed).
    virtual FrameStats advance(int steps, double elapsed) = 0;
    /// Whether the following advance() calls time their stages (where the backend can).
    virtual void setTiming(bool on) = 0;
    virtual const SimulationSettings& settings() const = 0;

    /// What the statistics show: simulated time, ½|v|², the basis's modes, a status line
    /// (integrator, viscosity, basis, mouse mode).
    virtual double time() const = 0;
    virtual double energy() const = 0;
    virtual int modeCount() const = 0;
    virtual std::string status() const = 0;
    /// The smoke now: per smoke cell of a grid scene; a surface's dye per vertex (in density,
    /// temperature empty).
    virtual SmokeFields smoke() const = 0;

    /// Draws the picture of `size` pixels in the byte order `blueFirst`, with `extras`.
    /// @throw modeflow::Error when a device call fails.
    virtual void draw(const PictureExtras& extras, VkExtent2D size, bool blueFirst) = 0;
    /// The last picture drawn.
    virtual const WindowPicture& picture() const = 0;
};

/// The scene of a prepared run on `backend`, drawn on `context` (the screen's device); all three
/// must outlive it.
/// @throw modeflow::Error as the scene's parts do.
std::unique_ptr<StirScene> makeStirScene(const Backend& backend, const RunInputs& run,
                                         const StirSettings& settings,
                                         const vulkan::VulkanContext& context);

}  // namespace modeflow::stir
