/// `modeflow stir` from the command line: what it refuses before any work. (The window itself
/// is tested under Xvfb by tests/engine/StirWindowSlowTest and tests/tools/StirCommandWindowTest.)

#include <cstdlib>
#include <fstream>

#include "tests/support/CliFixture.h"

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

}  // namespace
}  // namespace modeflow::testing
