/// @file ClosedFormCacheTest.cpp
/// A closed-form basis travels through the cache as descriptors (a few dozen bytes a mode, not a
/// column of the grid) and comes back equal, its columns never stored.

#include <gtest/gtest.h>

#include <filesystem>

#include "engine/format/CacheFile.h"
#include "engine/format/SeparableModes.h"
#include "precompute/Precompute.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

TEST(ClosedFormCache, StoresDescriptorsAndReadsThemBack) {
    SceneSpec scene = testing::gridScene({12, 10, 8}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 3);
    scene.basis.velocityModes = {{1, 200}};
    scene.basis.scalarModes = 6;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    ASSERT_EQ(cache.velocity.source, BasisSource::ClosedForm);
    EXPECT_EQ(cache.velocity.modes.cols(), 0);
    EXPECT_EQ(cache.velocity.separable.size(), 200u);

    const testing::TestFolder dir;
    writeCache(dir / "box.mfbasis", cache);
    // 200 dense columns on 2 556 faces would be 4 MB; the descriptors are 8 kB (the coefficients
    // take the rest).
    EXPECT_LT(fs::file_size(dir / "box.mfbasis"), 2'000'000u);
    const BasisCache read = readCache(dir / "box.mfbasis");
    EXPECT_EQ(read.velocity.source, BasisSource::ClosedForm);
    EXPECT_EQ(read.scalar.source, BasisSource::ClosedForm);
    EXPECT_EQ(read.velocity.modes.cols(), 0);
    EXPECT_EQ(read.velocity.separable, cache.velocity.separable);
    EXPECT_EQ(read.scalar.separable, cache.scalar.separable);
    EXPECT_EQ(read.coefficients.value, cache.coefficients.value);
    EXPECT_EQ(read.coefficients.k, cache.coefficients.k);
}

}  // namespace
}  // namespace modeflow
