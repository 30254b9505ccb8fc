/// @file PrecomputeMemorySlowTest.cpp
/// The precompute's memory estimate against the peak resident memory of `modeflow precompute`
/// itself (as the operating system counts it): conservative, but less than twice the peak.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include "precompute/PrecomputeMemory.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/CliFixture.h"
#include "tests/support/Sanitizers.h"
#include "tests/support/SceneFixtures.h"
#include "tests/support/TestFolder.h"

extern char** environ;

namespace modeflow {
namespace {

namespace fs = std::filesystem;

/// Peak resident bytes of `modeflow precompute SCENE` into a fresh cache folder.
double measuredPeak(const fs::path& scene, const fs::path& cache) {
    const std::string cli = testing::cliPath(), command = "precompute", dir = "--cache-dir";
    const std::string scenePath = scene.string(), cachePath = cache.string();
    char* argv[] = {const_cast<char*>(cli.c_str()),       const_cast<char*>(command.c_str()),
                    const_cast<char*>(scenePath.c_str()), const_cast<char*>(dir.c_str()),
                    const_cast<char*>(cachePath.c_str()), nullptr};
    posix_spawn_file_actions_t quiet;
    posix_spawn_file_actions_init(&quiet);
    posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
    pid_t child = 0;
    if (posix_spawn(&child, cli.c_str(), &quiet, nullptr, argv, environ) != 0) return 0.0;
    posix_spawn_file_actions_destroy(&quiet);
    int status = 0;
    rusage usage{};
    wait4(child, &status, 0, &usage);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << scene;
    return double(usage.ru_maxrss) * 1024.0;  // kilobytes on Linux
}

TEST(PrecomputeMemorySlow, TheEstimateIsConservativeButLessThanTwiceThePeak) {
    if (testing::kAddressSanitizer)
        GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine change the peak";
    const testing::TestFolder dir;
    const std::string disk = testing::replaced(testing::sceneFixture("small_disk_2d"),
                                               {{"[24, 24]", "[128, 128]"},
                                                {"velocity_modes = 8", "velocity_modes = 100"},
                                                {"scalar_modes = 4", "scalar_modes = 0"}});
    const std::string ball = testing::sceneFixture("unit_ball_3d");
    // 400 modes: block Lanczos (precompute/solve/EigenMethod.h), its search space the peak.
    const std::string blocks = testing::replaced(
        ball, {{"velocity_modes = 60", "velocity_modes = 400\ncoefficients = \"tensor-free\""}});
    // A whole box with free-slip walls: closed-form bases, sparse coefficients (2.2 million).
    const std::string box = testing::replaced(testing::sceneFixture("unit_box_3d"),
                                              {{"[10, 8, 6]", "[64, 64, 64]"},
                                               {"velocity_modes = 30", "velocity_modes = 1000"},
                                               {"scalar_modes = 5", "scalar_modes = 0"}});
    for (const auto& [name, text] :
         {std::pair{"disk.toml", disk}, std::pair{"ball.toml", ball},
          std::pair{"blocks.toml", blocks}, std::pair{"box.toml", box}}) {
        const fs::path scene = dir / name;
        std::ofstream(scene) << text;
        const PrecomputeMemory memory = estimatePrecomputeMemory(loadScene(scene));
        const double estimate = memory.peakBytes;
        if (text == blocks) EXPECT_EQ(memory.peakStage, "velocity eigensolve");
        const double peak = measuredPeak(scene, dir / "cache");
        std::cout << name << ": estimate " << estimate / 1048576.0 << " MiB, peak "
                  << peak / 1048576.0 << " MiB\n";
        EXPECT_GE(estimate / peak, 1.0) << name << ": estimate " << estimate << ", peak " << peak;
        EXPECT_LE(estimate / peak, 2.0) << name << ": estimate " << estimate << ", peak " << peak;
    }
}

}  // namespace
}  // namespace modeflow
