/// @file ModeMaterializationTest.cpp
/// A closed-form basis travels through the cache as descriptors and becomes dense columns only
/// when a run asks, after a memory check.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "engine/core/Error.h"
#include "engine/format/CacheFile.h"
#include "engine/format/ModeMaterialization.h"
#include "precompute/Precompute.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

BasisCache wholeBox(int modes) {
    SceneSpec scene = testing::gridScene({12, 10, 8}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, 3);
    scene.basis.velocityModes = {{1, modes}};
    scene.basis.scalarModes = 6;
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

TEST(ModeMaterialization, TheCacheStoresDescriptorsAndARunGetsTheColumns) {
    BasisCache cache = wholeBox(200);
    ASSERT_EQ(cache.velocity.source, BasisSource::ClosedForm);
    EXPECT_EQ(cache.velocity.modes.cols(), 0);
    EXPECT_EQ(cache.velocity.separable.size(), 200u);

    const testing::TestFolder dir;
    writeCache(dir / "box.mfbasis", cache);
    // 200 dense columns on 2 556 faces would be 4 MB; the descriptors are 8 kB.
    EXPECT_LT(fs::file_size(dir / "box.mfbasis"), 2'000'000u);
    BasisCache read = readCache(dir / "box.mfbasis");
    EXPECT_EQ(read.velocity.source, BasisSource::ClosedForm);
    EXPECT_EQ(read.scalar.source, BasisSource::ClosedForm);
    EXPECT_EQ(read.velocity.separable, cache.velocity.separable);
    EXPECT_EQ(read.scalar.separable, cache.scalar.separable);
    EXPECT_EQ(read.coefficients.value, cache.coefficients.value);

    materializeVelocityModes(read);
    ASSERT_EQ(read.velocity.modes.cols(), 200);
    EXPECT_EQ(read.velocity.modes, velocityModeFluxes(read.grid, read.faces, read.velocity.separable));
    const Eigen::MatrixXd gram = read.velocity.modes.transpose() * read.faceStar.asDiagonal() * read.velocity.modes;
    EXPECT_LE((gram - Eigen::MatrixXd::Identity(200, 200)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ModeMaterialization, AColumnsMatrixThatDoesNotFitIsRefused) {
    BasisCache cache = wholeBox(300);
    ::setenv("MODEFLOW_MEMORY_LIMIT", "1000000", 1);  // 1 MB < 300 × 2 556 faces × 8 bytes
    try {
        materializeVelocityModes(cache);
        ADD_FAILURE() << "materialized beyond the memory limit";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("closed-form velocity basis (300 modes on"), std::string::npos) << message;
        EXPECT_NE(message.find("lower the velocity modes"), std::string::npos) << message;
    }
    ::unsetenv("MODEFLOW_MEMORY_LIMIT");
    EXPECT_EQ(cache.velocity.modes.cols(), 0);
}

}  // namespace
}  // namespace modeflow
