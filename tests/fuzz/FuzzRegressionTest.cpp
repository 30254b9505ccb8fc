/// Every input a fuzz target once failed on (tests/fuzz/regressions/<Target>/) and every seed
/// (tests/fuzz/corpus/<Target>/), replayed through the target in the plain build: each must be
/// accepted, or refused with a printable modeflow::Error, and keep the target's promises. Seeds
/// must be accepted, but for those named refused-*: a seed that a change of the format or the
/// scene schema made stale would only fuzz the first check that refuses it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>

#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {
namespace {

namespace fs = std::filesystem;

struct Target {
    const char* name;
    bool (*entry)(std::string_view);
};

const Target kTargets[] = {{"SceneLoader", sceneLoader},
                           {"CacheReader", cacheReader},
                           {"ObjReader", objReader},
                           {"CheckpointReader", checkpointReader},
                           {"InputScript", inputScript}};

void PrintTo(const Target& target, std::ostream* out) {
    *out << target.name;
}

class FuzzRegression : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzRegression, EveryKeptInputIsAcceptedOrRefusedCleanly) {
    int replayed = 0;
    for (const char* folder : {"regressions", "corpus"}) {
        const fs::path inputs =
            fs::path(MODEFLOW_SOURCE_DIR) / "tests/fuzz" / folder / GetParam().name;
        if (!fs::is_directory(inputs)) continue;
        for (const auto& file : fs::directory_iterator(inputs)) {
            std::ifstream in(file.path(), std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
            const bool mustBeAccepted = std::string_view(folder) == "corpus" &&
                                        !file.path().filename().string().starts_with("refused-");
            try {
                EXPECT_TRUE(GetParam().entry(bytes) || !mustBeAccepted)
                    << file.path() << ": a seed is refused: " << lastRefusal();
            } catch (const std::exception& e) {
                ADD_FAILURE() << file.path() << ": " << e.what();
            }
            ++replayed;
        }
    }
    EXPECT_GT(replayed, 0) << "no seeds in tests/fuzz/corpus/" << GetParam().name;
}

INSTANTIATE_TEST_SUITE_P(Fuzz, FuzzRegression, ::testing::ValuesIn(kTargets),
                         [](const ::testing::TestParamInfo<Target>& info) {
                             return std::string(info.param.name);
                         });

}  // namespace
}  // namespace modeflow::fuzz
