/// `modeflow stir` run as users run it, in a window under Xvfb (tests/CMakeLists.txt wraps files
/// named *WindowTest in xvfb-run), with the validation layer on: on a Vulkan device, and on the
/// CPU reference with the window on the first suitable device.

#include <cstdlib>
#include <string>

#include "tests/support/CliFixture.h"
#include "tests/support/PngFile.h"

namespace modeflow::testing {
namespace {

/// A 12³ ball with 6 velocity modes and a warm source.
const char* kSmallBall = R"(
[grid]
resolution = [12, 12, 12]
bounds_min = [-1.1, -1.1, -1.1]
bounds_max = [1.1, 1.1, 1.1]
[[domain]]
shape = "ball"
center = [0.0, 0.0, 0.0]
radius = 1.0
[basis]
velocity_modes = 6
scalar_modes = 0
[[source]]
shape = "ball"
center = [0.0, 0.0, -0.5]
radius = 0.3
density = 1.5
temperature = 1.0
)";

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

}  // namespace
}  // namespace modeflow::testing
