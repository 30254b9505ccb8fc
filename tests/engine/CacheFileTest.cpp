/// @file CacheFileTest.cpp
/// The cache file keeps the vorticity quadrature and a cache without a tensor (tensor-free)
/// through a write and a read, and refuses a quadrature or storage that does not fit its layout.

#include <gtest/gtest.h>

#include <string>

#include "engine/core/Error.h"
#include "engine/format/CacheFile.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

using Storage = BasisCache::Coefficients::Storage;

std::string readError(const std::filesystem::path& path) {
    try {
        readCache(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(CacheFile, KeepsTheQuadratureAndAMissingTensor) {
    const testing::TestFolder folder;
    BasisCache cache = testing::disk2d();
    ASSERT_GT(cache.quadrature.curl.rows(), 0);
    cache.coefficients = BasisCache::Coefficients{};
    cache.coefficients.storage = Storage::None;
    writeCache(folder / "c.mfbasis", cache);
    const BasisCache read = readCache(folder / "c.mfbasis");
    EXPECT_EQ(read.coefficients.storage, Storage::None);
    EXPECT_TRUE(read.coefficients.packed.empty());
    for (const auto& [got, want] : {std::pair{&read.quadrature.curl, &cache.quadrature.curl},
                                    std::pair{&read.quadrature.velocityB, &cache.quadrature.velocityB},
                                    std::pair{&read.quadrature.velocityC, &cache.quadrature.velocityC}}) {
        EXPECT_EQ(got->start, want->start);
        EXPECT_EQ(got->column, want->column);
        EXPECT_EQ(got->value, want->value);
    }
}

TEST(CacheFile, RefusesAQuadratureOutsideTheFaces) {
    const testing::TestFolder folder;
    BasisCache cache = testing::disk2d();
    cache.quadrature.velocityB.column.front() = std::int32_t(cache.faces.size());
    writeCache(folder / "c.mfbasis", cache);
    const std::string error = readError(folder / "c.mfbasis");
    EXPECT_NE(error.find("is corrupt"), std::string::npos) << error;
}

TEST(CacheFile, RefusesQuadratureRowsThatDoNotAgree) {
    const testing::TestFolder folder;
    BasisCache cache = testing::disk2d();
    cache.quadrature.velocityC.start.pop_back();
    cache.quadrature.velocityC.column.resize(std::size_t(cache.quadrature.velocityC.start.back()));
    cache.quadrature.velocityC.value.resize(cache.quadrature.velocityC.column.size());
    writeCache(folder / "c.mfbasis", cache);
    const std::string error = readError(folder / "c.mfbasis");
    EXPECT_NE(error.find("is corrupt"), std::string::npos) << error;
}

TEST(CacheFile, RefusesAnUnknownStorage) {
    const testing::TestFolder folder;
    BasisCache cache = testing::disk2d();
    cache.coefficients.storage = Storage(7);
    writeCache(folder / "c.mfbasis", cache);
    const std::string error = readError(folder / "c.mfbasis");
    EXPECT_NE(error.find("is corrupt"), std::string::npos) << error;
}

}  // namespace
}  // namespace modeflow
