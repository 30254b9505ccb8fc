#pragma once
/// @file TestFolder.h
/// Where tests write files: a fresh temporary folder per test, and a folder for pictures worth
/// looking at after a run.

#include <filesystem>

namespace modeflow::testing {

/// A new, empty folder under the system's temporary folder ($TMPDIR or /tmp), named after the
/// running test and unique (mkdtemp: CTest runs tests in parallel processes); removed with all it
/// holds, read-only parts included, when the object goes. A fixture member or a local.
class TestFolder {
public:
    TestFolder();
    ~TestFolder();
    TestFolder(const TestFolder&) = delete;
    TestFolder& operator=(const TestFolder&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    operator const std::filesystem::path&() const { return mPath; }
    std::filesystem::path operator/(const std::filesystem::path& name) const {
        return mPath / name;
    }

private:
    std::filesystem::path mPath;
};

/// The folder for sample pictures a person may want to look at (PreviewTest's): the environment's
/// MODEFLOW_TEST_ARTIFACTS, else test-artifacts in the build tree; created when missing.
std::filesystem::path artifactFolder();

}  // namespace modeflow::testing
