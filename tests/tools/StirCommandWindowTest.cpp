/// `modeflow stir` run as users run it, in a window under Xvfb (tests/CMakeLists.txt wraps files
/// named *WindowTest in xvfb-run), with the validation layer on: on a Vulkan device, and on the
/// CPU reference with the window on the first suitable device; a surface scene's dye moves
/// with a scripted drag over the sphere in the screenshot.

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#include "tests/support/CliFixture.h"
#include "tests/support/PngFile.h"
#include "tests/support/SceneFixtures.h"

namespace modeflow::testing {
namespace {

/// A 12³ ball with 6 velocity modes and a warm source.
const std::string kSmallBall = sceneFixture("small_ball_3d");

/// The unit sphere of scenes/meshes (642 vertices) at rest, with dye from the north pole for the
/// first 0.4 s.
const char* kSphereSurface = R"(
[surface]
mesh = "sphere.obj"
[basis]
velocity_modes = 15
scalar_modes = 35
[output]
steps_per_frame = 2
[[source]]
shape = "ball"
center = [0.0, 0.0, 1.0]
radius = 0.3
density = 1.0
end = 0.4
)";

/// The mean column of a picture's orange (dyed) pixels, and how many there are.
std::pair<double, int> orangeColumn(const PngPixels& png) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x) {
            const std::size_t p = (std::size_t(y) * std::size_t(png.width) + std::size_t(x)) * 4;
            if (int(png.rgba[p]) - int(png.rgba[p + 2]) > 40) sum += x, ++count;
        }
    return {count > 0 ? sum / count : -1.0, count};
}

/// The 2D disk with a source.
std::string smallDisk() {
    return std::string(kSmallDisk) +
           "[[source]]\nshape = \"ball\"\ncenter = [0.0, -0.5]\nradius = 0.3\ndensity = "
           "1.5\ntemperature = 1.0\n";
}

class StirCommandWindow : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        // The commands inherit it; stir fails on any validation message.
        setenv("MODEFLOW_VULKAN_VALIDATION", "1", 1);
    }

    /// Runs 30 frames of `sceneText` on `device` in a 320 × 240 window and checks the summary
    /// and the screenshot.
    void stirs(const std::string& sceneText, const std::string& device) {
        const fs::path s = scene("scene.toml", sceneText), shot = mDir / "shot.png";
        const RunResult r = run("stir " + s.string() + " --device " + device +
                                " --frames 30 --width 320 --height 240 --screenshot " +
                                shot.string() + " --cache-dir " + mCache.string());
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_NE(r.err.find("30 frames (320x240)"), std::string::npos) << r.err;
        const std::optional<PngPixels> png = readPng(shot);
        ASSERT_TRUE(png) << "no screenshot at " << shot;
        int bright = 0;
        for (std::size_t p = 0; p < png->rgba.size(); p += 4)
            bright += png->rgba[p] + png->rgba[p + 1] + png->rgba[p + 2] > 3 * 128;
        EXPECT_EQ(png->width, 320);
        EXPECT_EQ(png->height, 240);
        EXPECT_GT(bright, 50) << "bright (smoke) pixels in the screenshot";
    }
};

TEST_F(StirCommandWindow, CpuReferenceStirsA2DScene) {
    stirs(smallDisk(), "cpu");
}

TEST_F(StirCommandWindow, CpuReferenceStirsA3DScene) {
    stirs(kSmallBall, "cpu");
}

TEST_F(StirCommandWindow, VulkanDeviceStirsA2DScene) {
    stirs(smallDisk(), "vulkan");
}

TEST_F(StirCommandWindow, DragOverASurfaceMovesItsDyeInTheScreenshot) {
    fs::copy_file(fs::path(MODEFLOW_SOURCE_DIR) / "scenes/meshes/sphere.obj", mDir / "sphere.obj");
    const fs::path s = scene("sphere.toml", kSphereSurface);
    // Left to right across the top of the sphere, through the dye at the pole; and the same
    // drag in the window's top margin, off the sphere.
    const auto dragAt = [&](const std::string& name, double y) {
        std::ofstream script(mDir / name);
        script << "0.10 down 0.30 " << y << "\n";
        for (int i = 1; i <= 6; ++i)
            script << 0.10 + 0.05 * i << " move " << 0.30 + 0.4 * i / 6.0 << " " << y << "\n";
        script << "0.45 up 0.70 " << y << "\n";
        return mDir / name;
    };
    const std::string over = dragAt("over.txt", 0.15).string(),
                      off = dragAt("off.txt", 0.02).string();
    std::vector<PngPixels> shots;
    for (const std::string& script : {std::string(), over, off}) {
        const fs::path shot = mDir / ("shot" + std::to_string(shots.size()) + ".png");
        const RunResult r = run("stir " + s.string() +
                                " --device cpu --frames 40 --width 320 "
                                "--height 240 --screenshot " +
                                shot.string() + " --cache-dir " + mCache.string() +
                                (script.empty() ? "" : " --script " + script));
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_NE(r.err.find("40 frames (320x240)"), std::string::npos) << r.err;
        const std::optional<PngPixels> png = readPng(shot);
        ASSERT_TRUE(png) << "no screenshot at " << shot;
        shots.push_back(*png);
    }
    const auto [still, stillCount] = orangeColumn(shots[0]);
    const auto [dragged, draggedCount] = orangeColumn(shots[1]);
    ASSERT_GT(stillCount, 200) << "dyed pixels without a drag";
    ASSERT_GT(draggedCount, 200) << "dyed pixels after the drag";
    EXPECT_GT(dragged, still + 15.0) << "the dye's mean column, without and after the drag";
    // Below the statistics' lines (whose frame rate varies from run to run).
    const std::size_t below = std::size_t(48 * shots[0].width * 4);
    EXPECT_TRUE(std::equal(shots[2].rgba.begin() + below, shots[2].rgba.end(),
                           shots[0].rgba.begin() + below, shots[0].rgba.end()))
        << "a drag off the sphere changed the picture";
}

}  // namespace
}  // namespace modeflow::testing
