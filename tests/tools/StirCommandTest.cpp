/// `modeflow stir` from the command line: what it refuses before any work, and the offscreen
/// loop that needs no display. (The window itself is tested under Xvfb by
/// tests/engine/StirWindowSlowTest and tests/tools/StirCommandWindowTest.)

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <tuple>

#include "engine/vulkan/VulkanContext.h"
#include "tests/support/CliFixture.h"
#include "tests/support/PngFile.h"
#include "tests/support/SceneFixtures.h"

namespace modeflow::testing {
namespace {

using StirCommand = Cli;

TEST_F(StirCommand, WithoutADisplaySaysSoAndHowToRunHeadless) {
    // The commands inherit this process's environment.
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    const fs::path s = scene("disk.toml", kSmallDisk);
    expectRejected("stir " + s.string() + " --frames 1 --cache-dir " + mCache.string(),
                   "no display");
    const RunResult r = run("stir " + s.string() + " --frames 1 --cache-dir " + mCache.string());
    EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
}

TEST_F(StirCommand, BadScriptsAreRefusedBeforeAnyWork) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    const fs::path script = mDir / "drag.txt";
    std::ofstream(script) << "0.1 down 0.2 0.2\n0.2 wiggle 0.3 0.3\n";
    expectRejected(
        "stir " + s.string() + " --script " + script.string() + " --cache-dir " + mCache.string(),
        "drag.txt:2: unknown event \"wiggle\"");
    expectRejected("stir " + s.string() + " --script " + (mDir / "missing.txt").string() +
                       " --cache-dir " + mCache.string(),
                   (mDir / "missing.txt").string() + ": no such input script");
    expectRejected("stir " + s.string() + " --device gpu --cache-dir " + mCache.string(),
                   "--device gpu");
}

TEST_F(StirCommand, ABasisTooLargeForTheDeviceIsRefusedBeforeThePrecompute) {
    // Just past the device's texel limit for the N × N float32 pair sums of an assembled tensor
    // (a whole box's closed-form basis): refused from the scene, with no cache made.
    const vulkan::VulkanContext device{vulkan::VulkanContextOptions{}};
    const int n = int(std::sqrt(double(device.texelBufferLimit()) / 4.0)) + 8;
    const fs::path s = scene(
        "box.toml", replaced(sceneFixture("unit_box_3d"),
                             {{"[10, 8, 6]", "[24, 24, 24]"},
                              {"velocity_modes = 30", "velocity_modes = " + std::to_string(n)},
                              {"scalar_modes = 5", "scalar_modes = 0"}}));
    expectRejected("stir " + s.string() + " --offscreen --frames 1 --cache-dir " + mCache.string(),
                   "the pair sums of N = " + std::to_string(n) + " modes");
}

TEST_F(StirCommand, AScreenshotOrPictureThatCannotBeMadeIsRefusedBeforeThePrecompute) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    const std::string stir =
        "stir " + s.string() + " --offscreen --frames 1 --cache-dir " + mCache.string() + " ";
    fs::create_directories(mDir / "folder");
    expectRejected(stir + "--screenshot " + (mDir / "missing" / "shot.png").string(),
                   "--screenshot " + (mDir / "missing" / "shot.png").string() + ": its folder " +
                       (mDir / "missing").string() + " does not exist");
    expectRejected(stir + "--screenshot " + (mDir / "folder").string(),
                   "--screenshot " + (mDir / "folder").string() + ": is a folder; name a file");

    // One row more than a storage buffer of the device holds at the widest window.
    const vulkan::VulkanContext device{vulkan::VulkanContextOptions{}};
    const VkDeviceSize rows = device.storageBufferLimit() / 4 / 16384 + 1;
    if (rows > 16384) GTEST_SKIP() << "this device takes every window size";
    const std::string size = "16384 × " + std::to_string(rows);
    expectRejected(stir + "--width 16384 --height " + std::to_string(rows),
                   "--width/--height: a picture of " + size + " pixels takes " +
                       std::to_string(4 * 16384 * rows) +
                       " bytes, more than the largest storage buffer of this device (" +
                       std::to_string(device.storageBufferLimit()) +
                       " bytes); at this shape it takes at most 1638");
}

TEST_F(StirCommand, OffscreenNeedsNoDisplayAndKeepsItsScreenshot) {
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    setenv("MODEFLOW_VULKAN_VALIDATION", "1", 1);  // stir fails on any validation message
    const fs::path s = scene("disk.toml", kSmallDisk), shot = mDir / "shot.png";
    // Nothing would close it without a frame count: refused before the precompute.
    expectRejected("stir " + s.string() + " --offscreen --cache-dir " + mCache.string(),
                   "--offscreen needs --frames");
    const RunResult r =
        run("stir " + s.string() + " --offscreen --frames 12 --width 320 --height " +
            "200 --screenshot " + shot.string() + " --cache-dir " + mCache.string());
    unsetenv("MODEFLOW_VULKAN_VALIDATION");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("12 frames (320x200)"), std::string::npos) << r.err;
    const std::optional<PngPixels> png = readPng(shot);
    ASSERT_TRUE(png) << "no screenshot at " << shot;
    EXPECT_EQ(png->width, 320);
    EXPECT_EQ(png->height, 200);
    const bool drawn =
        std::any_of(png->rgba.begin(), png->rgba.end(), [](unsigned char c) { return c > 100; });
    EXPECT_TRUE(drawn) << "the screenshot is black: nothing was drawn offscreen";
}

/// Pixels of exactly the particle colour (preview/Palette.h kParticle) in a screenshot.
long particlePixels(const PngPixels& png) {
    long count = 0;
    for (std::size_t p = 0; p + 3 < png.rgba.size(); p += 4)
        count += png.rgba[p] == 214 && png.rgba[p + 1] == 178 && png.rgba[p + 2] == 40;
    return count;
}

TEST_F(StirCommand, ParticlesAreDrawnOverTheSmokeIn2DAnd3D) {
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    setenv("MODEFLOW_VULKAN_VALIDATION", "1", 1);  // stir fails on any validation message
    for (const auto& [name, fixture, centre] :
         {std::tuple{"disk", kSmallDisk, "[0.0, 0.0]"},
          std::tuple{"ball", sceneFixture("small_ball_3d"), "[0.0, 0.0, 0.0]"}}) {
        const std::string text = fixture + "\n[[particles]]\nshape = \"ball\"\ncenter = " + centre +
                                 "\nradius = 0.5\ncount = 400\n";
        const fs::path s = scene(std::string(name) + ".toml", text), shot = mDir / "dots.png";
        const RunResult r =
            run("stir " + s.string() + " --offscreen --frames 3 --width 320 " +
                "--height 240 --screenshot " + shot.string() + " --cache-dir " + mCache.string());
        ASSERT_EQ(r.status, 0) << r.err;
        const std::optional<PngPixels> png = readPng(shot);
        ASSERT_TRUE(png) << name;
        EXPECT_GT(particlePixels(*png), 400) << name << ": the particles are drawn";
        // Without particles there are none of their colour.
        const fs::path plain = scene(std::string(name) + "_plain.toml", fixture);
        ASSERT_EQ(run("stir " + plain.string() +
                      " --offscreen --frames 3 --width 320 --height 240 "
                      "--screenshot " +
                      shot.string() + " --cache-dir " + mCache.string())
                      .status,
                  0);
        EXPECT_EQ(particlePixels(*readPng(shot)), 0) << name;
    }
    unsetenv("MODEFLOW_VULKAN_VALIDATION");
}

}  // namespace
}  // namespace modeflow::testing
