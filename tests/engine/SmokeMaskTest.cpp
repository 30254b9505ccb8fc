/// The smoke mask comes from the cache: the mask file round-trips and refuses what is stale or
/// damaged, and a run's setup reads it instead of rebuilding the domain (rebuilding it only
/// when the file is missing or damaged).

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"
#include "engine/format/SmokeMaskFile.h"
#include "precompute/geometry/FluidMask.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

class SmokeMaskTest : public ::testing::Test {
protected:
    testing::TestFolder mFolder;
};

std::vector<std::uint8_t> randomMask(std::size_t cells, unsigned seed) {
    std::mt19937 random(seed);
    std::vector<std::uint8_t> mask(cells);
    for (auto& m : mask) m = std::uint8_t(random() % 2);
    return mask;
}

void expectRefused(const fs::path& file, std::uint64_t key, int scale, std::size_t cells,
                   const std::string& why) {
    try {
        readSmokeMask(file, key, scale, cells);
        ADD_FAILURE() << "accepted: " << why;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
}

TEST_F(SmokeMaskTest, FileRoundTripsAndRefusesStaleOrDamagedMasks) {
    const fs::path file = mFolder / "m.mfmask";
    const std::vector<std::uint8_t> mask = randomMask(1001, 3);
    writeSmokeMask(file, 42, 2, mask);
    EXPECT_EQ(readSmokeMask(file, 42, 2, mask.size()), mask);
    expectRefused(file, 43, 2, mask.size(), "another basis");
    expectRefused(file, 42, 3, mask.size(), "another basis");
    expectRefused(file, 42, 2, mask.size() + 1, "another basis");  // the same byte count
    expectRefused(file, 42, 2, mask.size() + 100, "wrong size");
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(60);
        f.put(char(0x5a));
    }
    expectRefused(file, 42, 2, mask.size(), "damaged");
    fs::resize_file(file, 30);
    expectRefused(file, 42, 2, mask.size(), "wrong size");
    expectRefused(mFolder / "missing.mfmask", 42, 2, mask.size(), "missing");
}

SceneSpec diskScene() {
    SceneSpec scene = testing::unitBallScene(2, 20, 4, 0);
    scene.name = "mask_test";
    scene.smoke.resolutionScale = 2;
    return scene;
}

TEST_F(SmokeMaskTest, ARunReadsTheMaskFileBesideTheCacheAndRebuildsADamagedOne) {
    const SceneSpec scene = diskScene();
    Progress quiet = Progress::silent();
    const RunInputs first = prepareRun(scene, mFolder, quiet);
    const fs::path maskFile = smokeMaskPath(first.cachePath, 2);
    ASSERT_TRUE(fs::exists(maskFile)) << "the first run wrote no mask file";
    EXPECT_EQ(first.smokeMask, fluidMask(scene, first.cache, 2));

    // A valid file with other contents: a run that reads it gets those, one that rebuilt the
    // domain would not.
    const std::uint64_t key = fnv1a64(first.cache.key);
    std::vector<std::uint8_t> marked = first.smokeMask;
    marked[0] = 1;
    writeSmokeMask(maskFile, key, 2, marked);
    EXPECT_EQ(prepareRun(scene, mFolder, quiet).smokeMask, marked);

    fs::resize_file(maskFile, 10);
    EXPECT_EQ(prepareRun(scene, mFolder, quiet).smokeMask, first.smokeMask);
    EXPECT_EQ(readSmokeMask(maskFile, key, 2, first.smokeMask.size()), first.smokeMask)
        << "not rewritten";
}

TEST_F(SmokeMaskTest, AtSmokeScaleOneNoMaskFileIsNeeded) {
    SceneSpec scene = diskScene();
    scene.smoke.resolutionScale = 1;
    Progress quiet = Progress::silent();
    const RunInputs run = prepareRun(scene, mFolder, quiet);
    EXPECT_FALSE(fs::exists(smokeMaskPath(run.cachePath, 1)));
    EXPECT_EQ(run.smokeMask, fluidMask(scene, run.cache, 1));
}

}  // namespace
}  // namespace modeflow
