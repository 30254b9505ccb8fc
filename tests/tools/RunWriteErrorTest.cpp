/// @file RunWriteErrorTest.cpp
/// `modeflow run` when the output cannot be written (a full disk, a quota): the run stops with
/// one clear message and a non-zero status, and leaves only whole frames behind. The write error
/// is real: the run is started with a file size limit (`ulimit -f`, with SIGXFSZ ignored so the
/// write fails with EFBIG instead of killing the process), as a full disk fails a write.

#include <cstdlib>
#include <string>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "engine/output/VdbFrame.h"
#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
namespace fs = std::filesystem;

const std::string kSmokyDisk = std::string(testing::kSmallDisk) + R"(
[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.3
density = 5.0
temperature = 1.0
[smoke]
buoyancy = 1.0
resolution_scale = 2
[output]
frames = 40
steps_per_frame = 1
)";

using RunWriteError = Cli;

TEST_F(RunWriteError, StopsWithAMessageAndLeavesOnlyWholeFrames) {
    const fs::path scene = this->scene("smoky.toml", kSmokyDisk);
    ASSERT_EQ(run(precompute(scene)).status, 0) << "the cache is made without the limit";
    const fs::path out = mDir / "frames", err = mDir / "run-err.txt";
    // 40 KiB per file: the first two frames (little smoke yet) and the checkpoint fit, the third
    // frame does not (about 44 KiB).
    const std::string command =
        "bash -c \"trap '' XFSZ; ulimit -f 40; exec env -u MODEFLOW_CACHE_DIR " +
        testing::cliPath() + " run " + scene.string() + " --out " + out.string() + " --cache-dir " +
        mCache.string() + "\" >/dev/null 2>" + err.string() + " </dev/null";
    const int raw = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 1);
    const std::string message = testing::slurp(err);
    EXPECT_NE(message.find("modeflow: error: "), std::string::npos) << message;
    EXPECT_NE(message.find("File too large"), std::string::npos) << message;

    int frames = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "a partial file was left: " << name;
        if (entry.path().extension() != ".vdb") continue;
        ++frames;
        // Every frame left behind is whole: OpenVDB reads it and its metadata.
        const VdbFrameInfo info = readVdbFrameInfo(entry.path());
        EXPECT_TRUE(info.frame.has_value()) << name;
        EXPECT_FALSE(info.grids.empty()) << name;
    }
    EXPECT_GT(frames, 0) << "the limit was meant to let the first frames through";
    EXPECT_LT(frames, 40);
}

}  // namespace
}  // namespace modeflow
