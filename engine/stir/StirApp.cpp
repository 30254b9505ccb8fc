#include "engine/stir/StirApp.h"

#include <chrono>
#include <cstdio>
#include <ostream>
#include <thread>

#include "engine/core/Error.h"
#include "engine/display/NullScreen.h"
#include "engine/display/WindowScreen.h"
#include "engine/stir/RealTimeClock.h"
#include "engine/stir/StirKeys.h"
#include "engine/stir/StirScene.h"
#include "engine/stir/StirStatistics.h"

namespace modeflow::stir {
namespace {

using Clock = std::chrono::steady_clock;
using display::InputEvent;
using display::InputKind;
using display::MouseButton;

/// Steps may use this much of a frame in real time, so the window keeps at least ~30 fps.
constexpr double kStepBudgetSeconds = 1.0 / 30.0;
/// On CPU devices, where every pixel drawn costs (tools/README.md, "Interactive stirring"), a
/// default window smaller than kWindowWidth × kWindowHeight keeps a 2D 128² scene above 30 fps.
constexpr int kCpuWindowWidth = 960, kCpuWindowHeight = 540;

double seconds(Clock::duration d) {
    return std::chrono::duration<double>(d).count();
}

/// One run of the loop: everything it keeps between frames.
class StirLoop {
public:
    StirLoop(const StirOptions& options, const RunInputs& run, display::Screen& screen)
        : mOptions(options),
          mSceneSpec(run.scene),
          mScreen(screen),
          mContext(screen.context()),
          mBackend(options.backend.kind, mContext),
          mScene(makeStirScene(mBackend, run, options.stir, mContext)),
          mClock(mScene->settings().dt, kStepBudgetSeconds),
          mStatistics(run.scene.name, mBackend.capabilities().stageTimes),
          mScript(options.script) {}
    /// The screen may still be copying the last picture out of the renderer's buffer (when the
    /// loop ends by an exception). Not waitIdle(): a destructor must not throw.
    ~StirLoop() { vkDeviceWaitIdle(mContext.device()); }
    StirLoop(const StirLoop&) = delete;
    StirLoop& operator=(const StirLoop&) = delete;

    StirReport run(std::ostream& log);

private:
    void handle(const InputEvent& event);
    void act(StirAction action);
    /// PAUSED, SLOW MOTION ×…, or empty.
    std::string state(bool frameClock) const;

    const StirOptions& mOptions;
    const SceneSpec& mSceneSpec;
    display::Screen& mScreen;
    const vulkan::VulkanContext& mContext;
    Backend mBackend;
    std::unique_ptr<StirScene> mScene;
    RealTimeClock mClock;
    StirStatistics mStatistics;
    std::vector<TimedEvent> mScript;
    std::size_t mNextScripted = 0;

    bool mPaused = false, mStepOnce = false, mHelp = false, mQuit = false, mScreenshot = false;
    bool mArrows = false;
    bool mOrbiting = false;
    double mOrbitX = 0.0, mOrbitY = 0.0;
    int mScreenshots = 0;
};

void StirLoop::handle(const InputEvent& event) {
    switch (event.kind) {
        case InputKind::Key:
            if (const auto action = actionOfKey(event.key)) act(*action);
            break;
        case InputKind::ButtonDown:
            if (event.button == MouseButton::Left) {
                mScene->press(event.x, event.y, mScreen.extent());
            } else {
                mOrbiting = true;
            }
            mOrbitX = event.x;
            mOrbitY = event.y;
            break;
        case InputKind::ButtonUp:
            if (event.button == MouseButton::Left) {
                mScene->moveTo(event.x, event.y, mScreen.extent());
                mScene->release();
            } else {
                mOrbiting = false;
            }
            break;
        case InputKind::Move:
            mScene->moveTo(event.x, event.y, mScreen.extent());
            if (mOrbiting) mScene->orbit(event.x - mOrbitX, event.y - mOrbitY);
            mOrbitX = event.x;
            mOrbitY = event.y;
            break;
        case InputKind::Scroll:
            mScene->zoom(event.y);
            break;
        case InputKind::Resize:
            mScreen.resize(event.width, event.height);
            break;
    }
}

void StirLoop::act(StirAction action) {
    switch (action) {
        case StirAction::Pause:
            mPaused = !mPaused;
            mClock.restart();
            break;
        case StirAction::Step:
            mStepOnce = mPaused;
            break;
        case StirAction::Reset:
            mScene->reset();
            break;
        case StirAction::Integrator:
            mScene->toggleIntegrator();
            break;
        case StirAction::ViscosityUp:
            mScene->scaleViscosity(true);
            break;
        case StirAction::ViscosityDown:
            mScene->scaleViscosity(false);
            break;
        case StirAction::NextBasis:
            mScene->nextBasis();
            break;
        case StirAction::Paddle:
            mScene->togglePaddle();
            break;
        case StirAction::Arrows:
            mArrows = !mArrows;
            break;
        case StirAction::Screenshot:
            mScreenshot = true;
            break;
        case StirAction::Help:
            mHelp = !mHelp;
            break;
        case StirAction::Quit:
            mQuit = true;
            break;
    }
}

std::string StirLoop::state(bool frameClock) const {
    if (mPaused) return "PAUSED";
    if (frameClock || !mClock.isSlowMotion()) return "";
    char speed[48];
    std::snprintf(speed, sizeof speed, "SLOW MOTION x%.2f", mClock.speed());
    return speed;
}

StirReport StirLoop::run(std::ostream& log) {
    log << mContext.describe();
    StirReport report;
    const bool frameClock = mOptions.frames.has_value();
    const SimulationSettings& settings = mScene->settings();
    double screenClock = 0.0;
    const Clock::time_point start = Clock::now();
    Clock::time_point last = start;
    while (!mQuit && !mScreen.closeRequested() &&
           !(frameClock && report.frames >= *mOptions.frames)) {
        const Clock::time_point now = Clock::now();
        const double wallElapsed = seconds(now - last);
        last = now;
        const double elapsed = frameClock ? settings.stepsPerFrame * settings.dt : wallElapsed;
        screenClock += elapsed;

        for (const InputEvent& event : mScreen.poll()) handle(event);
        while (mNextScripted < mScript.size() && mScript[mNextScripted].time <= screenClock + 1e-9)
            handle(mScript[mNextScripted++].event);

        int steps = 0;
        if (mPaused)
            steps = std::exchange(mStepOnce, false) ? settings.stepsPerFrame : 0;
        else
            steps = frameClock ? settings.stepsPerFrame
                               : mClock.stepsFor(wallElapsed, mStatistics.stepSeconds());
        const Clock::time_point stepStart = Clock::now();
        mScene->setTiming(mStatistics.timesNextSteps());
        const FrameStats stats = mScene->advance(steps, elapsed);
        mStatistics.addSteps(steps, seconds(Clock::now() - stepStart), stats);
        mStatistics.countFrame(mScene->energy(), mScene->time(), mScene->status(),
                               state(frameClock));

        const Clock::time_point drawStart = Clock::now();
        const VkExtent2D size = mScreen.nextPictureSize();
        if (size.width == 0 || size.height == 0) {
            // Minimized: nothing to draw; wait a little rather than spin.
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            continue;
        }
        // The arrows scale with the energy now, not at the last refresh of the statistics (a
        // wall-clock time), so a scripted run draws the same arrows on any machine.
        const PictureExtras extras{mOptions.statistics ? mStatistics.text() : std::string(), mHelp,
                                   mArrows, mArrows ? mScene->energy() : 0.0};
        mScene->draw(extras, size, mScreen.blueFirst());
        if (std::exchange(mScreenshot, false)) {
            char name[64];
            std::snprintf(name, sizeof name, "_stir_%04d.png", ++mScreenshots);
            const std::filesystem::path file = mOptions.screenshotFolder / (mSceneSpec.name + name);
            mScene->picture().saveScreenshot(file);
            log << "screenshot: " << file.string() << "\n";
        }
        mScreen.present(mScene->picture().pixels());
        mStatistics.addPicture(seconds(Clock::now() - drawStart));
        ++report.frames;
    }
    report.seconds = seconds(Clock::now() - start);
    report.steps = mStatistics.steps();
    report.stepMs = mStatistics.stepMs();
    report.drawMs = mStatistics.pictureMs();
    if (!mOptions.screenshot.empty()) mScene->picture().saveScreenshot(mOptions.screenshot);
    mContext.waitIdle();
    report.width = int(mScene->picture().extent().width);
    report.height = int(mScene->picture().extent().height);
    report.smoke = mScene->smoke();
    report.simulatedTime = mScene->time();
    report.modes = mScene->modeCount();
    report.status = mScene->status();
    report.validationMessages = mContext.validationMessageCount();
    char summary[200];
    std::snprintf(
        summary, sizeof summary,
        "%d frames (%dx%d) in %.2f s: %.1f fps, %d steps, %.2f ms per step, %.2f ms per picture\n",
        report.frames, report.width, report.height, report.seconds, report.framesPerSecond(),
        report.steps, report.stepMs, report.drawMs);
    log << summary;
    if (report.validationMessages > 0)
        throw Error("the Vulkan validation layer reported " +
                    std::to_string(report.validationMessages) +
                    " problems; the first: " + mContext.validationMessages().front());
    return report;
}

}  // namespace

StirReport runStir(const StirOptions& options, const RunInputs& run, display::Screen& screen,
                   std::ostream& log) {
    StirLoop loop(options, run, screen);
    return loop.run(log);
}

StirReport runStir(const StirOptions& options, const RunInputs& run, std::ostream& log) {
    if (options.offscreen) {
        if (!options.frames)
            throw Error("stir offscreen needs a frame count (--frames): nothing closes it");
        const vulkan::VulkanContext context(options.backend.vulkan);
        const bool cpu = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
        const bool sized = options.width || options.height;
        display::NullScreen screen(
            context, options.width.value_or(cpu && !sized ? kCpuWindowWidth : kWindowWidth),
            options.height.value_or(cpu && !sized ? kCpuWindowHeight : kWindowHeight), false,
            false);
        return runStir(options, run, screen, log);
    }
    display::WindowScreen window(options.width.value_or(kWindowWidth),
                                 options.height.value_or(kWindowHeight),
                                 "modeflow stir: " + run.scene.name, options.backend.vulkan);
    if (!options.width && !options.height &&
        window.context().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
        window.resize(kCpuWindowWidth, kCpuWindowHeight);  // the first frames follow it
    return runStir(options, run, window, log);
}

}  // namespace modeflow::stir
