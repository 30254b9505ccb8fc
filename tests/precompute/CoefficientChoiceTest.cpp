/// @file CoefficientChoiceTest.cpp
/// `[basis] coefficients` in the precompute (precompute/CoefficientChoice.h): tensor-free
/// assembles nothing and keeps the quadrature; a scene that asks for a tensor later gets it
/// assembled into the same cache, equal to a direct precompute's; auto leaves the tensor out when
/// it would not fit or would cost more per step than the tensor-free advection.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "engine/format/CacheFile.h"
#include "precompute/CoefficientChoice.h"
#include "precompute/Precompute.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

using Storage = BasisCache::Coefficients::Storage;

SceneSpec diskScene(CoefficientStorage storage) {
    SceneSpec scene = testing::unitBallScene(2, 24, 8, 0);
    scene.basis.coefficients = storage;
    return scene;
}

TEST(CoefficientChoice, TensorFreeAssemblesNothingAndALaterTensorIsTheDirectOne) {
    const testing::TestFolder folder;
    Progress quiet = Progress::silent();
    const CacheOutcome free =
        ensureCache(diskScene(CoefficientStorage::TensorFree), folder, false, quiet);
    EXPECT_EQ(free.cache.coefficients.storage, Storage::None);
    EXPECT_TRUE(free.cache.coefficients.packed.empty());
    EXPECT_GT(free.cache.quadrature.curl.rows(), 0);

    // The same basis (the key does not depend on the storage), now wanted dense: assembled once
    // into the cache file, without a new eigensolve.
    const CacheOutcome dense =
        ensureCache(diskScene(CoefficientStorage::Dense), folder, false, quiet);
    EXPECT_TRUE(dense.reused);
    EXPECT_EQ(dense.path, free.path);
    ASSERT_EQ(dense.cache.coefficients.storage, Storage::Dense);
    EXPECT_EQ(readCache(dense.path).coefficients.storage, Storage::Dense);

    const BasisCache direct = computeBasis(diskScene(CoefficientStorage::Dense), quiet);
    EXPECT_EQ(dense.cache.coefficients.packed, direct.coefficients.packed);
}

TEST(CoefficientChoice, SparseIsStoredSparseWhenAsked) {
    Progress quiet = Progress::silent();
    const BasisCache sparse = computeBasis(diskScene(CoefficientStorage::Sparse), quiet);
    const BasisCache dense = computeBasis(diskScene(CoefficientStorage::Dense), quiet);
    ASSERT_EQ(sparse.coefficients.storage, Storage::Sparse);
    ASSERT_EQ(dense.coefficients.storage, Storage::Dense);
    EXPECT_EQ(sparse.coefficients.density, dense.coefficients.density);
    EXPECT_EQ(double(sparse.coefficients.value.size()),
              std::round(dense.coefficients.density * double(dense.coefficients.packed.size())));
}

TEST(CoefficientChoice, AutoLeavesTheTensorOutWhenItCostsMorePerStep) {
    // Tensor-free streams 2·V·N values, the tensor N²(N−1)/2: the crossover is N(N−1) = 4·c·V.
    const std::int64_t faces = 10000;
    const int crossover = int(std::floor(0.5 + std::sqrt(4.0 * kTensorFreeValueCost * faces)));
    EXPECT_TRUE(chooseTensor(CoefficientStorage::Auto, crossover - 5, faces).assemble);
    const TensorChoice beyond = chooseTensor(CoefficientStorage::Auto, crossover + 5, faces);
    EXPECT_FALSE(beyond.assemble);
    EXPECT_NE(beyond.reason.find("auto: the tensor-free advection streams fewer values per step"),
              std::string::npos)
        << beyond.reason;
    EXPECT_TRUE(chooseTensor(CoefficientStorage::Dense, 10 * crossover, faces).assemble);
    EXPECT_TRUE(chooseTensor(CoefficientStorage::Sparse, 10 * crossover, faces).assemble);
    EXPECT_FALSE(chooseTensor(CoefficientStorage::TensorFree, 10, faces).assemble);
}

TEST(CoefficientChoice, AutoLeavesOutATensorThatWouldNotFit) {
    // 100 modes: a 3.96 MB tensor, below the cost crossover of a million faces.
    setenv("MODEFLOW_MEMORY_LIMIT", "12000000", 1);
    const TensorChoice tight = chooseTensor(CoefficientStorage::Auto, 100, 1000000);
    setenv("MODEFLOW_MEMORY_LIMIT", "20000000", 1);
    const bool roomy = chooseTensor(CoefficientStorage::Auto, 100, 1000000).assemble;
    unsetenv("MODEFLOW_MEMORY_LIMIT");
    EXPECT_FALSE(tight.assemble);
    EXPECT_NE(tight.reason.find("exceed a quarter of the"), std::string::npos) << tight.reason;
    EXPECT_TRUE(roomy);
}

}  // namespace
}  // namespace modeflow
