#pragma once
/// @file StirApp.h
/// `modeflow stir`: the interactive loop. Each frame reads the input (the screen's, and a
/// script's events when their time comes), takes the simulation steps the clock calls for
/// (RealTimeClock: real time, or slow motion that says so), draws the scene (StirScene: a grid's
/// smoke on the device, or a surface's dye, with the StirStatistics and the key help over it)
/// and presents it on a display::Screen: a window, or in tests a NullScreen. With a frame count the
/// clock is the scene's frame clock instead (steps_per_frame steps a frame), so a scripted run is
/// the same on any machine, and the loop ends after the last frame.

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/display/Screen.h"
#include "engine/run/Backend.h"
#include "engine/run/RunInputs.h"
#include "engine/simulation/SmokeFields.h"
#include "engine/stir/InputScript.h"
#include "engine/stir/StirSession.h"

namespace modeflow::stir {

/// The window's first size unless one is asked for: smaller on a CPU device (StirOptions).
inline constexpr int kWindowWidth = 1280, kWindowHeight = 720;

struct StirOptions {
    /// The window's first size, screen units (runStir with a window). Unset: 1280 × 720, or
    /// 960 × 540 on a CPU device (lavapipe), where drawing costs per pixel and the smaller window
    /// keeps 30 fps.
    std::optional<int> width, height;
    std::optional<int> frames;                     ///< close after this many frames (frame clock)
    std::filesystem::path screenshot;              ///< the last frame as PNG, if not empty
    std::filesystem::path screenshotFolder = ".";  ///< where the screenshot key writes
    std::vector<TimedEvent> script;                ///< events to replay
    bool statistics = true;                        ///< the statistics over the picture
    /// Draw into an offscreen picture instead of a window (no display needed; needs `frames`):
    /// benchmarks on headless GPUs, scripted runs that keep only the screenshot.
    bool offscreen = false;
    /// The backend that simulates: the screen's Vulkan device, or the CPU reference beside it.
    /// The window's device is `backend.vulkan`'s choice (the first suitable one that presents
    /// to the window for the CPU reference too).
    BackendChoice backend;
    StirSettings stir;
};

struct StirReport {
    int frames = 0;
    int steps = 0;
    double seconds = 0.0;        ///< wall time of the frame loop
    double stepMs = 0.0;         ///< mean wall time per simulation step
    double drawMs = 0.0;         ///< mean wall time per frame to draw and present
    int width = 0, height = 0;   ///< the last picture's size, pixels
    SmokeFields smoke;           ///< at the end (a surface's: the dye per vertex, StirScene.h)
    double simulatedTime = 0.0;  ///< at the end
    int modes = 0;               ///< of the basis shown at the end
    std::string status;          ///< StirSession::status() at the end
    std::size_t validationMessages = 0;
    double framesPerSecond() const { return seconds > 0.0 ? frames / seconds : 0.0; }
};

/// Runs on `screen` until the user quits, the screen is closed or the frame count is reached;
/// `log` gets the device report and a summary line. The screen's context is the display's
/// device (options.backend.vulkan is not used).
/// @throw modeflow::Error when the validation layer reported problems on the screen's context,
///        or when anything below fails.
StirReport runStir(const StirOptions& options, const RunInputs& run, display::Screen& screen,
                   std::ostream& log);

/// The same in a window (display::WindowScreen) opened for it, or with `options.offscreen` on a
/// display::NullScreen of that size on the chosen device.
/// @throw modeflow::Error without a display (with how to run headless), for a device that
///        cannot present, offscreen without a frame count, or as above.
StirReport runStir(const StirOptions& options, const RunInputs& run, std::ostream& log);

}  // namespace modeflow::stir
