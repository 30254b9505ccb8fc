#include "tests/support/TestFolder.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

#include "engine/core/Error.h"

namespace modeflow::testing {

namespace fs = std::filesystem;

namespace {

/// "Suite.Test" of the running test, with what a file name should not hold replaced.
std::string runningTestName() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "no-test";
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
    return name;
}

/// Makes every folder under `root` writable and searchable again, so that a test that took the
/// permissions away (to provoke a write error) cannot leave its folder behind.
void restorePermissions(const fs::path& root) {
    std::error_code ec;
    fs::permissions(root, fs::perms::owner_all, fs::perm_options::add, ec);
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_directory(ec))
            fs::permissions(it->path(), fs::perms::owner_all, fs::perm_options::add, ec);
}

}  // namespace

TestFolder::TestFolder() {
    std::string pattern =
        (fs::temp_directory_path() / ("modeflow-" + runningTestName() + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data()))
        throw Error("cannot create a temporary folder " + pattern + ": " + std::strerror(errno));
    mPath = pattern;
}

TestFolder::~TestFolder() {
    restorePermissions(mPath);
    std::error_code ec;
    fs::remove_all(mPath, ec);
}

fs::path artifactFolder() {
    const char* chosen = std::getenv("MODEFLOW_TEST_ARTIFACTS");
    const fs::path folder =
        chosen && *chosen ? fs::path(chosen) : fs::path(MODEFLOW_TEST_ARTIFACTS);
    fs::create_directories(folder);
    return folder;
}

}  // namespace modeflow::testing
