/// `modeflow stir`'s window, run for real: under Xvfb on lavapipe (tests/CMakeLists.txt wraps
/// files named *WindowTest and *WindowSlowTest in xvfb-run) with the validation layer on, driven
/// by input scripts on the frame clock, so every run is reproducible. Label `slow`
/// (tests/README.md).

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "engine/stir/StirApp.h"
#include "engine/stir/StirView.h"
#include "tests/support/PngFile.h"
#include "tests/support/StirRuns.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

using testing::drag;
using testing::preparedStirRun;

/// Scripted runs in a window, their screenshots in the test's own folder.
class StirWindowTest : public ::testing::Test {
protected:
    fs::path scratch(const std::string& name) const { return mFolder / name; }

    /// A scripted run in a 640 × 480 window (`sized` false: the default size), simulated on the
    /// window's device or on the CPU reference beside it.
    stir::StirReport run(int dim, const std::string& script, int frames = 40,
                         const fs::path& screenshot = {}, bool sized = true,
                         BackendKind backend = BackendKind::Vulkan) const {
        stir::StirOptions options;
        options.backend.kind = backend;
        if (sized) {
            options.width = 640;
            options.height = 480;
        }
        options.frames = frames;
        options.screenshot = screenshot;
        options.screenshotFolder = mFolder;
        options.statistics = false;
        options.backend.vulkan.validation = true;
        options.script = stir::parseInputScript(script, "test script");
        std::ostringstream log;
        return stir::runStir(options, preparedStirRun(dim), log);
    }

    testing::TestFolder mFolder;
};

Vec3 smokeCentroid(int dim, const stir::StirReport& report) {
    return testing::smokeCentroid(dim, report.smoke.density);
}

/// The horizontal centre of the bright pixels of a PNG (testing::brightCentreX), and its size.
double brightCentreX(const fs::path& png, int& width, int& height) {
    const std::optional<testing::PngPixels> read = testing::readPng(png);
    if (!read) return -1.0;
    width = read->width;
    height = read->height;
    preview::Image picture(width, height);
    picture.rgba = read->rgba;
    return testing::brightCentreX(picture);
}

TEST_F(StirWindowTest, DragCarriesTheSmokeAlongAndThePictureShowsIt) {
    const fs::path still = scratch("still.png"), right = scratch("right.png");
    const stir::StirReport none = run(2, "", 40, still);
    const stir::StirReport toRight = run(2, drag(0.3, 0.7), 40, right);
    const stir::StirReport toLeft = run(2, drag(0.7, 0.3), 40);
    EXPECT_EQ(none.validationMessages, 0u);
    const double x0 = smokeCentroid(2, none)[0];
    EXPECT_NEAR(x0, 0.0, 0.02) << "without a drag the plume rises straight";
    EXPECT_GT(smokeCentroid(2, toRight)[0], x0 + 0.1);
    EXPECT_LT(smokeCentroid(2, toLeft)[0], x0 - 0.1);
    // The screenshots show the same: the bright smoke moved right.
    int w0 = 0, h0 = 0, w1 = 0, h1 = 0;
    const double still0 = brightCentreX(still, w0, h0), moved = brightCentreX(right, w1, h1);
    EXPECT_EQ(w0, 640);
    EXPECT_EQ(h0, 480);
    ASSERT_GT(still0, 0.0) << "no smoke in the still screenshot";
    EXPECT_NEAR(still0, 320.0, 10.0);
    EXPECT_GT(moved, still0 + 20.0);
}

TEST_F(StirWindowTest, CpuReferenceDragMovesTheSmokeLikeTheDevice) {
    // The CPU reference simulates, the window's device draws its uploaded fields.
    const fs::path shot = scratch("cpu_right.png");
    const stir::StirReport device = run(2, drag(0.3, 0.7), 40);
    const stir::StirReport cpu = run(2, drag(0.3, 0.7), 40, shot, true, BackendKind::CpuReference);
    const stir::StirReport still = run(2, "", 40, {}, true, BackendKind::CpuReference);
    EXPECT_EQ(cpu.validationMessages, 0u);
    EXPECT_EQ(cpu.frames, 40);
    const double x0 = smokeCentroid(2, still)[0], moved = smokeCentroid(2, cpu)[0];
    EXPECT_GT(moved, x0 + 0.1);
    EXPECT_NEAR(moved, smokeCentroid(2, device)[0], 0.01)
        << "the CPU reference's smoke went elsewhere";
    int w = 0, h = 0;
    EXPECT_GT(brightCentreX(shot, w, h), 320.0 + 20.0) << "the picture shows the smoke moved right";
    EXPECT_EQ(w, 640);
}

TEST_F(StirWindowTest, PaddleFollowsTheDragAndPushesTheSmoke) {
    const stir::StirReport none = run(2, "0.0 key m\n", 40);
    const stir::StirReport pushed = run(2, drag(0.3, 0.7, "0.0 key m\n"), 40);
    EXPECT_NE(pushed.status.find("mouse: paddle"), std::string::npos) << pushed.status;
    EXPECT_GT(smokeCentroid(2, pushed)[0], smokeCentroid(2, none)[0] + 0.05);
}

TEST_F(StirWindowTest, WindowResizesWithoutErrors) {
    const fs::path shot = scratch("resized.png");
    const stir::StirReport report = run(2, "0.1 resize 800 400\n0.3 resize 320 240\n", 20, shot);
    EXPECT_EQ(report.width, 320);
    EXPECT_EQ(report.height, 240);
    EXPECT_EQ(report.frames, 20);
    int w = 0, h = 0;
    brightCentreX(shot, w, h);
    EXPECT_EQ(w, 320);
    EXPECT_EQ(h, 240);
}

TEST_F(StirWindowTest, DefaultWindowFitsTheDevice) {
    const stir::StirReport report = run(2, "", 5, {}, false);
    const bool cpu = vulkan::VulkanContext().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    EXPECT_EQ(report.width, cpu ? 960 : 1280);
    EXPECT_EQ(report.height, cpu ? 540 : 720);
}

TEST_F(StirWindowTest, KeysPauseSwitchAndReset) {
    // Paused from the start: no time passes, no smoke appears; one step key advances one frame.
    const stir::StirReport paused = run(2, "0.0 key space\n0.1 key s\n", 10);
    EXPECT_NEAR(paused.simulatedTime, 0.025, 1e-12);

    const stir::StirReport switched =
        run(2, "0.05 key i\n0.1 key ]\n0.15 key b\n0.2 key p\n0.25 key v\n0.7 key r\n", 30);
    EXPECT_NE(switched.status.find("explicit"), std::string::npos) << switched.status;
    EXPECT_EQ(switched.status.find("viscosity 0 "), std::string::npos) << switched.status;
    EXPECT_EQ(switched.modes, 10) << "b switches from 1-10,21-30 to the leading range";
    EXPECT_NE(switched.status.find("(1-10)"), std::string::npos) << switched.status;
    EXPECT_TRUE(fs::exists(scratch("stir_test_2d_stir_0001.png")));
    // Reset at 0.7 s: the clock restarted and the smoke is only what 0.05 s of emission made.
    EXPECT_LT(switched.simulatedTime, 0.1);

    const stir::StirReport back = run(2, "0.1 key b\n0.2 key b\n", 10);
    EXPECT_EQ(back.modes, 20) << "b cycles back to the whole basis";
}

TEST_F(StirWindowTest, ThreeDimensionalSceneOrbitsZoomsAndStirsAcrossTheView) {
    const std::string orbit =
        "0.05 rdown 0.5 0.5\n0.1 move 0.6 0.45\n0.15 rup 0.6 0.45\n0.15 scroll 2\n";
    const stir::StirReport none = run(3, orbit, 40);
    const std::string stroke =
        orbit + "0.2 down 0.3 0.7\n0.3 move 0.5 0.7\n0.4 move 0.7 0.7\n0.45 up 0.7 0.7\n";
    const stir::StirReport stirred = run(3, stroke, 40);
    EXPECT_EQ(stirred.validationMessages, 0u);
    // The smoke moves along the drag's direction in the scene: the stroke's two ends on the
    // plane through the box's centre, seen by the orbited and zoomed camera.
    stir::StirView view(MacGrid::fromSpec(preparedStirRun(3).cache.grid));
    view.orbit(0.1, -0.05);
    view.zoom(2);
    const auto from = view.scenePoint(0.3, 0.7, 640, 480), to = view.scenePoint(0.7, 0.7, 640, 480);
    ASSERT_TRUE(from && to);
    const Vec3 c0 = smokeCentroid(3, none), c1 = smokeCentroid(3, stirred);
    double along = 0.0, length = 0.0;
    for (int a = 0; a < 3; ++a) {
        along += (c1[a] - c0[a]) * ((*to)[a] - (*from)[a]);
        length += ((*to)[a] - (*from)[a]) * ((*to)[a] - (*from)[a]);
    }
    EXPECT_GT(along / std::sqrt(length), 0.05)
        << "smoke displacement along the stroke; centroid moved by " << c1[0] - c0[0] << ", "
        << c1[1] - c0[1] << ", " << c1[2] - c0[2];
}

}  // namespace
}  // namespace modeflow
