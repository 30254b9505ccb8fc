/// `modeflow stir`'s loop on a NullScreen: the clock, scripts, session, statistics, drawing and
/// screenshots without a window or a display (the real window: StirWindowSlowTest), on lavapipe
/// with the validation layer on, on the frame clock so every run is reproducible.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "engine/display/NullScreen.h"
#include "engine/stir/StirApp.h"
#include "engine/stir/StirStatistics.h"
#include "tests/support/PngFile.h"
#include "tests/support/StirRuns.h"
#include "tests/support/TestFolder.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow::testing {
namespace {

namespace fs = std::filesystem;

class StirLoopTest : public ::testing::Test {
protected:
    void SetUp() override {
        mContext = makeVulkanContext(true);
        ASSERT_NE(mContext, nullptr);
    }

    /// A scripted run of `frames` frames on `screen`.
    stir::StirReport run(display::NullScreen& screen, int dim, const std::string& script,
                         int frames = 40, BackendKind backend = BackendKind::Vulkan,
                         const fs::path& screenshot = {}) {
        stir::StirOptions options;
        options.backend.kind = backend;
        options.frames = frames;
        options.screenshot = screenshot;
        options.screenshotFolder = mDir;
        options.statistics = false;
        options.script = stir::parseInputScript(script, "test script");
        std::ostringstream log;
        return stir::runStir(options, preparedStirRun(dim), screen, log);
    }

    std::unique_ptr<vulkan::VulkanContext> mContext;
    TestFolder mFolder;
    const fs::path mDir = mFolder.path();
};

/// The fraction of pixels whose colour differs by more than `tolerance` in some channel.
double differingFraction(const preview::Image& a, const preview::Image& b, int tolerance) {
    if (a.width != b.width || a.height != b.height) return 1.0;
    std::size_t differing = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4)
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])) > tolerance) {
                ++differing;
                break;
            }
    return double(differing) / double(a.rgba.size() / 4);
}

TEST_F(StirLoopTest, DragOnANullScreenCarriesTheSmokeAndThePictureShowsIt) {
    display::NullScreen still(*mContext, 640, 480), moved(*mContext, 640, 480);
    const stir::StirReport none = run(still, 2, "");
    const stir::StirReport toRight = run(moved, 2, drag(0.3, 0.7));
    EXPECT_EQ(none.validationMessages + toRight.validationMessages, 0u);
    EXPECT_EQ(moved.presentedCount(), 40);
    EXPECT_GT(smokeCentroid(2, toRight.smoke.density)[0],
              smokeCentroid(2, none.smoke.density)[0] + 0.1);
    const double x0 = brightCentreX(still.lastPicture()), x1 = brightCentreX(moved.lastPicture());
    EXPECT_NEAR(x0, 320.0, 10.0);
    EXPECT_GT(x1, x0 + 20.0);
}

TEST_F(StirLoopTest, CpuReferencePicturesMatchTheDevicesArrowsIncluded) {
    // v: velocity arrows, drawn from the face velocity the CPU reference uploads each frame.
    const std::string script = drag(0.3, 0.7, "0.0 key v\n");
    display::NullScreen device(*mContext, 480, 480), cpu(*mContext, 480, 480);
    const stir::StirReport onDevice = run(device, 2, script, 30);
    const stir::StirReport onCpu = run(cpu, 2, script, 30, BackendKind::CpuReference);
    EXPECT_EQ(onCpu.validationMessages, 0u);
    EXPECT_NEAR(smokeCentroid(2, onCpu.smoke.density)[0],
                smokeCentroid(2, onDevice.smoke.density)[0], 0.01);
    EXPECT_LT(differingFraction(device.lastPicture(), cpu.lastPicture(), 8), 0.001)
        << "of the pixels differ between the device's and the CPU reference's picture";
    // The arrows are there: without them the picture differs.
    display::NullScreen plain(*mContext, 480, 480);
    run(plain, 2, drag(0.3, 0.7), 30, BackendKind::CpuReference);
    EXPECT_GT(differingFraction(plain.lastPicture(), cpu.lastPicture(), 8), 0.03)
        << "of the pixels are arrows";
}

TEST_F(StirLoopTest, ThreeDimensionalCpuReferenceIsDrawn) {
    display::NullScreen device(*mContext, 480, 360), cpu(*mContext, 480, 360);
    run(device, 3, "", 20);
    run(cpu, 3, "", 20, BackendKind::CpuReference);
    ASSERT_EQ(cpu.lastPicture().width, 480);
    EXPECT_LT(differingFraction(device.lastPicture(), cpu.lastPicture(), 8), 0.001)
        << "of the pixels differ between the device's and the CPU reference's picture";
    display::NullScreen empty(*mContext, 480, 360);
    run(empty, 3, "0.0 key space\n", 1, BackendKind::CpuReference);
    EXPECT_GT(differingFraction(empty.lastPicture(), cpu.lastPicture(), 24), 0.01)
        << "no smoke drawn";
}

TEST_F(StirLoopTest, ScreenshotIsThePresentedPictureInEitherByteOrder) {
    display::NullScreen rgba(*mContext, 320, 240), bgra(*mContext, 320, 240, true);
    const fs::path shot = mDir / "shot.png";
    run(rgba, 2, "", 20, BackendKind::Vulkan, shot);
    run(bgra, 2, "", 20);
    EXPECT_EQ(differingFraction(rgba.lastPicture(), bgra.lastPicture(), 0), 0.0)
        << "the blue-first screen shows other colours";
    const std::optional<testing::PngPixels> png = testing::readPng(shot);
    ASSERT_TRUE(png) << shot;
    preview::Image saved(png->width, png->height);
    saved.rgba = png->rgba;
    EXPECT_EQ(differingFraction(saved, rgba.lastPicture(), 0), 0.0);
}

TEST_F(StirLoopTest, ScriptResizesTheScreen) {
    display::NullScreen screen(*mContext, 640, 480);
    const stir::StirReport report = run(screen, 2, "0.1 resize 800 400\n0.3 resize 320 240\n", 20);
    EXPECT_EQ(report.width, 320);
    EXPECT_EQ(report.height, 240);
    EXPECT_EQ(screen.lastPicture().width, 320);
    EXPECT_EQ(screen.lastPicture().height, 240);
}

TEST_F(StirLoopTest, MinimizedScreenGetsNoPicturesWhileTheSimulationRunsOn) {
    display::NullScreen screen(*mContext, 320, 240);
    screen.minimizeFor(5);
    const stir::StirReport report = run(screen, 2, "", 20);
    EXPECT_EQ(report.frames, 20);
    EXPECT_EQ(screen.presentedCount(), 20);
    EXPECT_NEAR(report.simulatedTime, 25 * 0.025, 1e-9) << "5 minimized frames and 20 shown";
}

TEST_F(StirLoopTest, StatisticsShowTheirLinesOverThePicture) {
    display::NullScreen without(*mContext, 640, 480), with(*mContext, 640, 480);
    run(without, 2, "", 3);
    stir::StirOptions options;
    options.frames = 3;
    std::ostringstream log;
    stir::runStir(options, preparedStirRun(2), with, log);
    // The text sits at the top left, over the margin left of the square box.
    preview::Image corner(with.lastPicture()), plain(without.lastPicture());
    EXPECT_GT(differingFraction(corner, plain, 24), 0.002);
    EXPECT_NE(log.str().find("3 frames (640x480)"), std::string::npos) << log.str();
}

TEST(StirStatisticsTest, LinesSayTheStateAndStageTimesOnlyWhereMeasured) {
    const Backend cpu(BackendChoice{BackendKind::CpuReference, {}});
    const stir::StirSession session(cpu, preparedStirRun(2));
    stir::StirStatistics measured("scene", true), unmeasured("scene", false);
    FrameStats stats;
    stats.timedSteps = 2;
    stats.modalMs = 3.0;
    measured.addSteps(2, 0.010, stats);
    EXPECT_NEAR(measured.stepSeconds(), 0.005, 1e-12);
    measured.addSteps(1, 0.010, {});
    EXPECT_NEAR(measured.stepSeconds(), 0.8 * 0.005 + 0.2 * 0.010, 1e-12) << "smoothed";
    const double t = session.simulation().time();
    measured.countFrame(session.energy(), t, session.status(), "PAUSED");
    unmeasured.countFrame(session.energy(), t, session.status(), "");
    EXPECT_NE(measured.text().find("scene"), std::string::npos) << measured.text();
    EXPECT_NE(measured.text().find("PAUSED"), std::string::npos) << measured.text();
    EXPECT_NE(measured.text().find("modal 1.5"), std::string::npos) << measured.text();
    EXPECT_NE(measured.text().find(session.status()), std::string::npos) << measured.text();
    EXPECT_EQ(unmeasured.text().find("gpu ms"), std::string::npos) << unmeasured.text();
    EXPECT_EQ(measured.steps(), 3);
    EXPECT_NEAR(measured.stepMs(), 20.0 / 3.0, 1e-9);
}

}  // namespace
}  // namespace modeflow::testing
