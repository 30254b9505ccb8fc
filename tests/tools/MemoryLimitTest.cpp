/// @file MemoryLimitTest.cpp
/// Scenes the machine cannot hold are refused before any work, with the estimate against the
/// available memory (MODEFLOW_MEMORY_LIMIT stands in for the machine's MemAvailable here).

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

/// Sets MODEFLOW_MEMORY_LIMIT for the commands of one scope.
class MemoryLimit {
public:
    explicit MemoryLimit(const char* bytes) { setenv("MODEFLOW_MEMORY_LIMIT", bytes, 1); }
    ~MemoryLimit() { unsetenv("MODEFLOW_MEMORY_LIMIT"); }
};

TEST_F(Cli, APrecomputeBeyondTheMemoryLimitIsRefusedBeforeAnyWork) {
    const MemoryLimit limit("10000000");
    const RunResult r = run(precompute(scene("disk.toml", testing::kSmallDisk)));
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.err.rfind("modeflow: error: [grid].resolution = [24, 24]: the precompute (", 0), 0u)
        << r.err;
    EXPECT_NE(
        r.err.find("(estimate), but only 9.54 MiB are available (MODEFLOW_MEMORY_LIMIT); lower "
                   "[grid].resolution\n"),
        std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("measures"), std::string::npos) << "a stage began: " << r.err;
    EXPECT_EQ(cacheFiles(), 0);
}

TEST_F(Cli, ARunBeyondTheMemoryLimitIsRefusedBeforeThePrecompute) {
    const MemoryLimit limit("10000000");
    const std::string text = std::string(testing::kSmallDisk) + "[smoke]\nresolution_scale = 8\n";
    const RunResult r = run("run " + scene("disk.toml", text).string() + " --device cpu --out " +
                            (mDir / "frames").string() + " --cache-dir " + mCache.string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(
        r.err.rfind(
            "modeflow: error: [grid].resolution = [24, 24] with [smoke].resolution_scale = 8 "
            "(36864 smoke cells) and 8 velocity modes: the run on the CPU reference needs about ",
            0),
        0u)
        << r.err;
    EXPECT_EQ(cacheFiles(), 0);
    EXPECT_FALSE(fs::exists(mDir / "frames"));
}

TEST_F(Cli, ARunWithMoreParticlesThanTheMemoryHoldsIsRefusedBeforeThePrecompute) {
    const MemoryLimit limit("400000000");
    const std::string text = std::string(testing::kSmallDisk) +
                             "[[particles]]\nshape = \"ball\"\ncenter = [0, 0]\nradius = 0.5\n"
                             "count = 4000000\n";
    const RunResult r = run("run " + scene("disk.toml", text).string() + " --device cpu --out " +
                            (mDir / "frames").string() + " --cache-dir " + mCache.string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("(576 smoke cells), 8 velocity modes and 4000000 particles: the run on "
                         "the CPU reference needs about "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("lower the count or rate of the [[particles]] sets"), std::string::npos)
        << r.err;
    EXPECT_EQ(cacheFiles(), 0);
}

TEST_F(Cli, AMemoryLimitThatIsNotAByteCountIsRefused) {
    const MemoryLimit limit("8G");
    expectRejected(precompute(scene("disk.toml", testing::kSmallDisk)),
                   "MODEFLOW_MEMORY_LIMIT = \"8G\": expected a positive whole number of bytes");
}

}  // namespace
}  // namespace modeflow
