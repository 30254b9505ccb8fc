#include "engine/stir/StirApp.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <thread>

#include "engine/display/DisplayKernels.h"
#include "engine/display/Presenter.h"
#include "engine/display/TextOverlay.h"
#include "engine/display/Window.h"
#include "engine/device/Simulation.h"
#include "engine/core/Error.h"
#include "engine/preview/PngWriter.h"
#include "engine/preview/VolumeRenderer.h"
#include "engine/stir/RealTimeClock.h"
#include "engine/stir/StirKeys.h"
#include "engine/stir/StirView.h"

namespace modeflow::stir {
namespace {

using Clock = std::chrono::steady_clock;
using display::InputEvent;
using display::InputKind;
using display::MouseButton;

/// Steps may use this much of a frame in real time, so the window keeps at least ~30 fps.
constexpr double kStepBudgetSeconds = 1.0 / 30.0;
/// The window's default size, and on CPU devices, where every pixel drawn costs (about 24 ns on
/// lavapipe with two cores), a smaller one that keeps a 2D 128² scene above 30 fps.
constexpr int kWindowWidth = 1280, kWindowHeight = 720;
constexpr int kCpuWindowWidth = 960, kCpuWindowHeight = 540;
/// 3D: optical depth across the box at density 1.
constexpr float kOpticalDepth = 6.0f;

double seconds(Clock::duration d) {
    return std::chrono::duration<double>(d).count();
}

/// Device time per stage, summed over the timed steps between two refreshes of the statistics.
struct StageTimes {
    int steps = 0;
    double forces = 0.0, modal = 0.0, reconstruction = 0.0, obstacles = 0.0, advection = 0.0;

    void add(const FrameStats& s) {
        steps += s.timedSteps;
        forces += s.forcesMs;
        modal += s.modalMs;
        reconstruction += s.reconstructionMs;
        obstacles += s.obstaclesMs;
        advection += s.advectionMs;
    }
    /// Milliseconds per step, one line.
    std::string line() const {
        if (steps == 0) return "gpu ms per step: -";
        char text[160];
        std::snprintf(text, sizeof text, "gpu ms per step: forces %.1f  modal %.1f  velocity %.1f  smoke %.1f",
                      forces / steps, modal / steps, reconstruction / steps, advection / steps);
        std::string line = text;
        if (obstacles > 0.0) {
            std::snprintf(text, sizeof text, "  obstacles %.1f", obstacles / steps);
            line += text;
        }
        return line;
    }
};

/// One run of the window: everything the frame loop keeps between frames.
class StirWindow {
public:
    StirWindow(const StirOptions& options, const RunInputs& run)
        : mOptions(options),
          mScene(run.scene),
          mWindow(options.width.value_or(kWindowWidth), options.height.value_or(kWindowHeight),
                  "modeflow stir: " + run.scene.name),
          mContext(contextOptions(options.backend.vulkan, mWindow)),
          mBackend(options.backend.kind, mContext),
          mSession(mBackend, run, options.stir),
          mView(mSession.simulation().smokeGrid()),
          mPresenter(mContext, mWindow.framebufferSize()),
          mKernels(mContext),
          mOverlay(mContext),
          mSequence(mContext),
          mClock(mSession.settings().dt, kStepBudgetSeconds),
          mScript(options.script) {
        if (!options.width && !options.height &&
            mContext.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
            mWindow.resize(kCpuWindowWidth, kCpuWindowHeight);  // the first frames follow it
        if (mView.grid().dim == 3)
            mRenderer = std::make_unique<preview::VolumeRenderer>(
                mContext, mView.grid(), run.smokeMask, StirView::kPictureWidth, StirView::kPictureHeight);
    }

    StirReport run(std::ostream& log);

private:
    static vulkan::VulkanContextOptions contextOptions(vulkan::VulkanContextOptions options,
                                                       const display::Window& window) {
        options.instanceExtensions = window.requiredInstanceExtensions();
        options.createSurface = [&window](VkInstance instance) { return window.createSurface(instance); };
        return options;
    }

    void handle(const InputEvent& event);
    void act(StirAction action);
    std::optional<Vec3> scenePoint(const InputEvent& event) const;
    /// Draws the frame into mPixels (one submission); false while the window is minimized.
    bool draw();
    std::vector<display::TextBlock> overlayText(int scale) const;
    /// The paddle in the picture's source units, when paddle mode is on.
    display::PaddleOverlay paddleOverlay() const;
    preview::Image picture() const;
    void saveScreenshot(const std::filesystem::path& file);

    const StirOptions& mOptions;
    const SceneSpec& mScene;
    display::Window mWindow;
    vulkan::VulkanContext mContext;
    Backend mBackend;
    StirSession mSession;
    StirView mView;
    display::Presenter mPresenter;
    display::DisplayKernels mKernels;
    display::TextOverlay mOverlay;
    vulkan::CommandSequence mSequence;
    std::unique_ptr<preview::VolumeRenderer> mRenderer;
    std::unique_ptr<vulkan::DeviceBuffer> mPixels;
    VkExtent2D mPixelsExtent{};
    RealTimeClock mClock;
    std::vector<TimedEvent> mScript;
    std::size_t mNextScripted = 0;

    bool mPaused = false, mStepOnce = false, mHelp = false, mQuit = false, mScreenshot = false;
    bool mArrows = false;
    double mEnergy = 0.0;  ///< ½|v|² at the last statistics refresh
    bool mOrbiting = false;
    double mOrbitX = 0.0, mOrbitY = 0.0;
    int mScreenshots = 0;
    // Statistics, refreshed about four times a second.
    std::string mStatistics;
    double mStepSeconds = 0.0;  ///< smoothed wall time per step
    StageTimes mStages;
    int mSampleFrames = 0;
    Clock::time_point mSampleStart = Clock::now();
};

std::optional<Vec3> StirWindow::scenePoint(const InputEvent& event) const {
    const VkExtent2D size = mPresenter.extent();
    return mView.scenePoint(event.x, event.y, int(size.width), int(size.height));
}

void StirWindow::handle(const InputEvent& event) {
    switch (event.kind) {
        case InputKind::Key:
            if (const auto action = actionOfKey(event.key)) act(*action);
            break;
        case InputKind::ButtonDown:
            if (event.button == MouseButton::Left) {
                if (const auto p = scenePoint(event)) mSession.press(*p);
            } else {
                mOrbiting = true;
            }
            mOrbitX = event.x;
            mOrbitY = event.y;
            break;
        case InputKind::ButtonUp:
            if (event.button == MouseButton::Left) {
                if (const auto p = scenePoint(event)) mSession.moveTo(*p);
                mSession.release();
            } else {
                mOrbiting = false;
            }
            break;
        case InputKind::Move:
            if (const auto p = scenePoint(event)) mSession.moveTo(*p);
            if (mOrbiting && mView.grid().dim == 3) mView.orbit(event.x - mOrbitX, event.y - mOrbitY);
            mOrbitX = event.x;
            mOrbitY = event.y;
            break;
        case InputKind::Scroll:
            if (mView.grid().dim == 3) mView.zoom(event.y);
            break;
        case InputKind::Resize:
            mWindow.resize(event.width, event.height);
            break;
    }
}

void StirWindow::act(StirAction action) {
    switch (action) {
        case StirAction::Pause:
            mPaused = !mPaused;
            mClock.restart();
            break;
        case StirAction::Step: mStepOnce = mPaused; break;
        case StirAction::Reset: mSession.reset(); break;
        case StirAction::Integrator: mSession.toggleIntegrator(); break;
        case StirAction::ViscosityUp: mSession.scaleViscosity(true); break;
        case StirAction::ViscosityDown: mSession.scaleViscosity(false); break;
        case StirAction::NextBasis: mSession.nextBasis(); break;
        case StirAction::Paddle: mSession.togglePaddle(); break;
        case StirAction::Arrows: mArrows = !mArrows; break;
        case StirAction::Screenshot: mScreenshot = true; break;
        case StirAction::Help: mHelp = !mHelp; break;
        case StirAction::Quit: mQuit = true; break;
    }
}

std::vector<display::TextBlock> StirWindow::overlayText(int scale) const {
    std::vector<display::TextBlock> blocks;
    if (mOptions.statistics) blocks.push_back({8, 8, mStatistics, false});
    if (mHelp) {
        // Bottom right, clear of the statistics: actions flush right, keys in a column before.
        const HelpColumns help = helpColumns();
        const int margin = 8 * scale;
        blocks.push_back({-margin, -margin, help.actions, true});
        blocks.push_back({-(margin + display::textWidth(help.actions, scale) + 6 * scale), -margin,
                          help.keys, true});
    }
    return blocks;
}

display::PaddleOverlay StirWindow::paddleOverlay() const {
    display::PaddleOverlay overlay;
    const auto paddle = mSession.paddle();
    if (!paddle) return overlay;
    const MacGrid& grid = mView.grid();
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
    const auto centre = mView.project(paddle->centre), tip = mView.project(end);
    if (!centre || !tip) return overlay;
    overlay.centre[0] = float(centre->x);
    overlay.centre[1] = float(centre->y);
    overlay.axis[0] = float(tip->x - centre->x);
    overlay.axis[1] = float(tip->y - centre->y);
    overlay.radius = float(paddle->radius * centre->pixelsPerLength);
    overlay.shown = true;
    return overlay;
}

bool StirWindow::draw() {
    const VkExtent2D wanted = mWindow.framebufferSize();
    if (wanted.width == 0 || wanted.height == 0) return false;
    const VkExtent2D shown = mPresenter.extent();
    if (wanted.width != shown.width || wanted.height != shown.height) mPresenter.resize(wanted);
    const VkExtent2D size = mPresenter.extent();
    if (!mPixels || size.width != mPixelsExtent.width || size.height != mPixelsExtent.height) {
        mPixels = std::make_unique<vulkan::DeviceBuffer>(
            mContext, VkDeviceSize(size.width) * size.height * 4, "window picture");
        mPixelsExtent = size;
    }
    const int width = int(size.width), height = int(size.height);
    const int scale = height >= 600 ? 2 : 1;
    mOverlay.update(width, height, overlayText(scale), scale);
    display::DisplayTarget target{width, height, mView.viewport(width, height), mPresenter.blueFirst()};
    const auto* simulation = dynamic_cast<const device::Simulation*>(&mSession.simulation());
    if (!simulation) throw Error("the stir window draws a simulation on its Vulkan device only");
    const device::SmokeState& smoke = simulation->smokeState();
    if (mRenderer) {
        mRenderer->record(mSequence, smoke.fields(), kOpticalDepth, 2, mView.camera());
        mKernels.recordPicture(mSequence, mRenderer->pictureBuffer(), mRenderer->width(),
                               mRenderer->height(), paddleOverlay(), mOverlay.buffer(), target,
                               *mPixels);
    } else {
        display::Smoke2DLook look;
        look.hotScale = mSession.settings().simulatesTemperature() ? 1.0f : 0.0f;
        look.paddle = paddleOverlay();
        look.arrows = mArrows;
        if (mArrows) {
            // The RMS speed over the box, ½|v|² = ½∫|u|², spans half an arrow square.
            const MacGrid& grid = mView.grid();
            const double area = grid.spacing[0] * grid.cells[0] * grid.spacing[1] * grid.cells[1];
            const double rms = std::sqrt(2.0 * mEnergy / area);
            look.arrowSpacing = float(std::max(16, target.viewport.width / 24));
            look.arrowScale = float(0.5 * look.arrowSpacing / std::max(rms, 1e-6));
        }
        mKernels.recordSmoke2D(mSequence, smoke, simulation->faceVelocityBuffer(), look,
                               mOverlay.buffer(), target, *mPixels);
    }
    mSequence.submitAndWait();
    return true;
}

preview::Image StirWindow::picture() const {
    const int width = int(mPixelsExtent.width), height = int(mPixelsExtent.height);
    std::vector<std::uint32_t> words(std::size_t(width) * std::size_t(height));
    mPixels->download<std::uint32_t>(words);
    return preview::unpackImage(words, width, height, mPresenter.blueFirst());
}

void StirWindow::saveScreenshot(const std::filesystem::path& file) {
    if (!mPixels) throw Error("no frame was drawn, so there is no screenshot for " + file.string());
    preview::writePng(file, picture());
}

StirReport StirWindow::run(std::ostream& log) {
    log << mContext.describe();
    StirReport report;
    const bool frameClock = mOptions.frames.has_value();
    const SimulationSettings& settings = mSession.settings();
    double windowClock = 0.0, stepWall = 0.0, drawWall = 0.0;
    const Clock::time_point start = Clock::now();
    Clock::time_point last = start;
    while (!mQuit && !mWindow.closeRequested() &&
           !(frameClock && report.frames >= *mOptions.frames)) {
        const Clock::time_point now = Clock::now();
        const double wallElapsed = seconds(now - last);
        last = now;
        const double elapsed = frameClock ? settings.stepsPerFrame * settings.dt : wallElapsed;
        windowClock += elapsed;

        for (const InputEvent& event : mWindow.poll()) handle(event);
        while (mNextScripted < mScript.size() && mScript[mNextScripted].time <= windowClock + 1e-9)
            handle(mScript[mNextScripted++].event);

        int steps = 0;
        if (mPaused)
            steps = std::exchange(mStepOnce, false) ? settings.stepsPerFrame : 0;
        else
            steps = frameClock ? settings.stepsPerFrame : mClock.stepsFor(wallElapsed, mStepSeconds);
        const Clock::time_point stepStart = Clock::now();
        // Timestamps would double a step's cost on lavapipe: time one frame's steps per refresh
        // of the statistics.
        mSession.setTiming(mStages.steps == 0);
        const FrameStats stats = mSession.advance(steps, elapsed);
        mStages.add(stats);
        if (steps > 0) {
            const double took = seconds(Clock::now() - stepStart);
            stepWall += took;
            report.steps += steps;
            mStepSeconds = mStepSeconds > 0.0 ? 0.8 * mStepSeconds + 0.2 * took / steps : took / steps;
        }

        ++mSampleFrames;
        const double sampled = seconds(Clock::now() - mSampleStart);
        if (sampled >= 0.25 || mStatistics.empty()) {
            std::string state = mPaused ? "PAUSED" : "";
            if (!mPaused && !frameClock && mClock.isSlowMotion()) {
                char speed[48];
                std::snprintf(speed, sizeof speed, "SLOW MOTION x%.2f", mClock.speed());
                state = speed;
            }
            char line[256];
            std::snprintf(line, sizeof line, "%s   %.1f fps   step %.1f ms   energy %.4g   t %.2f s   %s",
                          mScene.name.c_str(), sampled > 0.0 ? mSampleFrames / sampled : 0.0,
                          1e3 * mStepSeconds, mEnergy = mSession.energy(), mSession.simulation().time(),
                          state.c_str());
            mStatistics = std::string(line) + "\n" + mStages.line() + "\n" + mSession.status() + "\nh: help";
            mStages = {};
            mSampleFrames = 0;
            mSampleStart = Clock::now();
        }

        const Clock::time_point drawStart = Clock::now();
        if (!draw()) {
            // Minimized: nothing to draw; wait a little rather than spin.
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            continue;
        }
        if (std::exchange(mScreenshot, false)) {
            char name[64];
            std::snprintf(name, sizeof name, "_stir_%04d.png", ++mScreenshots);
            const std::filesystem::path file = mOptions.screenshotFolder / (mScene.name + name);
            saveScreenshot(file);
            log << "screenshot: " << file.string() << "\n";
        }
        mPresenter.present(*mPixels, mWindow.framebufferSize());
        drawWall += seconds(Clock::now() - drawStart);
        ++report.frames;
    }
    report.seconds = seconds(Clock::now() - start);
    report.stepMs = report.steps > 0 ? 1e3 * stepWall / report.steps : 0.0;
    report.drawMs = report.frames > 0 ? 1e3 * drawWall / report.frames : 0.0;
    if (!mOptions.screenshot.empty()) saveScreenshot(mOptions.screenshot);
    mContext.waitIdle();
    report.width = int(mPixelsExtent.width);
    report.height = int(mPixelsExtent.height);
    report.smoke = mSession.simulation().smoke();
    report.simulatedTime = mSession.simulation().time();
    report.modes = mSession.modeCount();
    report.status = mSession.status();
    report.validationMessages = mContext.validationMessageCount();
    char summary[200];
    std::snprintf(summary, sizeof summary,
                  "%d frames (%dx%d) in %.2f s: %.1f fps, %d steps, %.2f ms per step, %.2f ms per picture\n",
                  report.frames, report.width, report.height, report.seconds, report.framesPerSecond(),
                  report.steps, report.stepMs, report.drawMs);
    log << summary;
    if (report.validationMessages > 0)
        throw Error("the Vulkan validation layer reported " + std::to_string(report.validationMessages) +
                    " problems; the first: " + mContext.validationMessages().front());
    return report;
}

}  // namespace

StirReport runStir(const StirOptions& options, const RunInputs& run, std::ostream& log) {
    StirWindow window(options, run);
    return window.run(log);
}

}  // namespace modeflow::stir
