#pragma once
/// @file TestFolder.h
/// A fresh folder for one test's files: under the system's temporary folder, named for the test
/// (and made unique, so parallel runs never share it), removed with the object.

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

namespace modeflow::testing {

class TestFolder {
public:
    TestFolder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string test =
            info ? std::string(info->test_suite_name()) + "_" + info->name() : "test";
        for (char& c : test)
            if (c == '/') c = '_';  // parameterized tests: Suite/Name/0
        mPath = std::filesystem::temp_directory_path() /
                ("modeflow_" + test + "_" + std::to_string(std::random_device{}()));
        std::filesystem::create_directories(mPath);
    }
    ~TestFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(mPath, ignored);
    }
    TestFolder(const TestFolder&) = delete;
    TestFolder& operator=(const TestFolder&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(const std::string& name) const { return mPath / name; }

private:
    std::filesystem::path mPath;
};

}  // namespace modeflow::testing
