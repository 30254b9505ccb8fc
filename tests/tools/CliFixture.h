#pragma once
/// @file CliFixture.h
/// Runs the real `modeflow` binary as users run it, in a fresh folder per test.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace modeflow::testing {

namespace fs = std::filesystem;

/// A 24² unit disk with 8 velocity modes: quick to precompute, for the command-line tests.
inline const char* kSmallDisk = R"(
[grid]
resolution = [24, 24]
bounds_min = [-1.1, -1.1]
bounds_max = [1.1, 1.1]
[[domain]]
shape = "ball"
center = [0.0, 0.0]
radius = 1.0
[basis]
velocity_modes = 8
scalar_modes = 4
)";

struct RunResult {
    int status = -1;
    std::string out, err;
};

inline std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        // One folder per test and process: parameterized names ("Case/param") become one level,
        // and the same test run from two build trees at once does not share it.
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '_');
        mDir = fs::temp_directory_path() / ("modeflow-cli-" + name + "-" + std::to_string(getpid()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
        mCache = mDir / "cache";
    }
    void TearDown() override { fs::remove_all(mDir); }

    RunResult run(const std::string& args) const {
        const fs::path out = mDir / "stdout.txt", err = mDir / "stderr.txt";
        const std::string cmd = "env -u MODEFLOW_CACHE_DIR " + std::string(MODEFLOW_CLI) + " " +
                                args + " >" + out.string() + " 2>" + err.string() + " </dev/null";
        const int raw = std::system(cmd.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
    }

    fs::path scene(const std::string& name, const std::string& text) const {
        const fs::path p = mDir / name;
        std::ofstream(p) << text;
        return p;
    }

    std::string precompute(const fs::path& s, const std::string& extra = "") const {
        return "precompute " + s.string() + " --cache-dir " + mCache.string() + " " + extra;
    }

    int cacheFiles() const {
        if (!fs::exists(mCache)) return 0;
        int n = 0;
        for (const auto& e : fs::directory_iterator(mCache)) n += e.is_regular_file();
        return n;
    }

    /// Expects failure with one clear message naming `needle`, and no cache written.
    void expectRejected(const std::string& args, const std::string& needle) const {
        const RunResult r = run(args);
        EXPECT_NE(r.status, 0) << args;
        EXPECT_NE(r.err.find(needle), std::string::npos) << "stderr: " << r.err;
        EXPECT_NE(r.err.find("error"), std::string::npos) << "stderr: " << r.err;
        EXPECT_EQ(cacheFiles(), 0) << args;
    }

    fs::path mDir, mCache;
};

}  // namespace modeflow::testing
