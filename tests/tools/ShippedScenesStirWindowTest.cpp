/// The scenes under scenes/ made for `modeflow stir` (those whose text names the command, e.g.
/// "modeflow stir scenes/stir_2d.toml") open their window under Xvfb and run a few frames on each
/// backend, with the validation layer on: one test per scene, named after it.
/// Long precomputes run on the reduced copy tests/support/ShippedScenes.h makes (stir_3d).

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/support/CliFixture.h"
#include "tests/support/PngFile.h"
#include "tests/support/ShippedScenes.h"

namespace modeflow::testing {
namespace {

constexpr int kFrames = 3;

/// The shipped scenes whose file names `modeflow stir`.
std::vector<fs::path> stirScenes() {
    std::vector<fs::path> found;
    for (const fs::path& relative : shippedScenes())
        if (slurp(scenesFolder() / relative).find("modeflow stir") != std::string::npos)
            found.push_back(relative);
    return found;
}

class ShippedStirScene : public Cli, public ::testing::WithParamInterface<fs::path> {
protected:
    void SetUp() override {
        Cli::SetUp();
        setenv("MODEFLOW_VULKAN_VALIDATION", "1", 1);  // stir fails on any validation message
    }
};

TEST_P(ShippedStirScene, StirsAFewFrames) {
    const SceneUnderTest s = sceneUnderTest(GetParam(), mDir / "reduced");
    std::cout << s.description << "\n";
    for (const std::string& backend : backendOptions()) {
        const fs::path shot = mDir / ("shot_" + backend + ".png");
        const std::string args = "stir " + s.file.string() + " --device " + backend + " --frames " +
                                 std::to_string(kFrames) + " --screenshot " + shot.string() +
                                 " --cache-dir " + mCache.string();
        const RunResult r = run(args);
        ASSERT_EQ(r.status, 0) << "stir --device " << backend << ": " << r.err;
        EXPECT_NE(r.err.find(std::to_string(kFrames) + " frames ("), std::string::npos) << r.err;
        const std::optional<PngPixels> png = readPng(shot);
        ASSERT_TRUE(png) << "no screenshot at " << shot;
        EXPECT_GT(png->width * png->height, 0);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedStirScene, ::testing::ValuesIn(stirScenes()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                             return sceneTestName(info.param);
                         });

TEST(ShippedStirScenes, IncludeTheStirDemos) {
    const std::vector<fs::path> scenes = stirScenes();
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), fs::path("stir_2d.toml")), scenes.end());
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), fs::path("stir_3d.toml")), scenes.end());
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), fs::path("sphere_surface.toml")),
              scenes.end());
}

}  // namespace
}  // namespace modeflow::testing
