#pragma once
/// @file CliFixture.h
/// Runs the real `modeflow` binary (or another of the project's programs) as users run it, in a
/// fresh folder per test.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/SceneFixtures.h"
#include "tests/support/TestFolder.h"

namespace modeflow::testing {

namespace fs = std::filesystem;

/// tests/data/scenes/small_disk_2d.toml, the 24² unit disk with 8 velocity modes: quick to
/// precompute, for the command-line tests (read when the test program starts).
inline const std::string kSmallDisk = sceneFixture("small_disk_2d");

struct RunResult {
    int status = -1;
    std::string out, err;
};

/// The whole content of a file.
std::string slurp(const fs::path& p);

/// The path of the `modeflow` binary the tests run.
std::string cliPath();

class Cli : public ::testing::Test {
protected:
    /// `modeflow ARGS` (a shell command line) with MODEFLOW_CACHE_DIR unset and no input.
    RunResult run(const std::string& args) const { return runProgram(cliPath(), args); }
    /// The same for another program.
    RunResult runProgram(const std::string& program, const std::string& args) const;

    /// Writes a scene file `name` into the test's folder.
    fs::path scene(const std::string& name, const std::string& text) const;

    /// "precompute SCENE --cache-dir <the test's cache> EXTRA".
    std::string precompute(const fs::path& s, const std::string& extra = "") const;

    /// How many files the test's cache folder holds.
    int cacheFiles() const;

    /// Expects failure with one clear message naming `needle`, and no cache written.
    void expectRejected(const std::string& args, const std::string& needle) const;

    TestFolder mFolder;
    const fs::path mDir = mFolder.path(), mCache = mFolder / "cache";
};

}  // namespace modeflow::testing
