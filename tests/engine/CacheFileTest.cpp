/// The cache file's reader: a real basis round-trips (its vorticity quadrature, and a cache
/// without a tensor, too), and every file that is not a whole, sound cache is refused with a
/// message, cheaply (the header is checked before the bulk is read).

#include <gtest/gtest.h>

#include <cmath>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/Error.h"
#include "engine/format/CacheFile.h"
#include "tests/support/PeakMemory.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestFolder.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;
using testing::peakMemoryMiB;
using testing::TestFolder;

/// The message readCache fails with ("accepted" when it does not).
std::string readError(const fs::path& file) {
    try {
        readCache(file);
    } catch (const Error& e) {
        return e.what();
    }
    return "accepted";
}

const BasisCache& smallBasis() {
    static const BasisCache cache = testing::sharedBasis(testing::unitBallScene(2, 10, 4, 2));
    return cache;
}

TEST(CacheFileTest, ARealBasisRoundTrips) {
    const TestFolder folder;
    writeCache(folder / "disk.mfbasis", smallBasis());
    const BasisCache read = readCache(folder / "disk.mfbasis");
    EXPECT_EQ(read.key, smallBasis().key);
    EXPECT_EQ(read.grid, smallBasis().grid);
    EXPECT_EQ(read.faces, smallBasis().faces);
    EXPECT_EQ(read.velocity.modes, smallBasis().velocity.modes);
    EXPECT_EQ(read.coefficients.packed, smallBasis().coefficients.packed);
    ASSERT_EQ(smallBasis().windBase.size(), 4u);  // a disk is [[domain]] walls
    EXPECT_EQ(read.windBase, smallBasis().windBase);
    ASSERT_EQ(smallBasis().windStokes.size(), 4u);
    EXPECT_EQ(read.windStokes, smallBasis().windStokes);
    EXPECT_EQ(readCacheKeyHash(folder / "disk.mfbasis"), fnv1a64(smallBasis().key));
}

TEST(CacheFileTest, AHugeFileIsRefusedByItsHeaderWithoutReadingIt) {
    const TestFolder folder;
    const fs::path notCache = folder / "big.mfbasis";
    std::ofstream(notCache) << "not a cache at all";
    fs::resize_file(notCache, std::uintmax_t{1} << 30);  // sparse: no disk used
    const long before = peakMemoryMiB();
    EXPECT_NE(readError(notCache).find("is not a modeflow basis cache (bad magic)"),
              std::string::npos)
        << readError(notCache);
    EXPECT_LT(peakMemoryMiB() - before, 64) << "MiB more at the peak: the file was read whole";

    // A sound header whose payload size is beyond the file: refused before any allocation.
    const fs::path cache = folder / "disk.mfbasis";
    writeCache(cache, smallBasis());
    std::fstream header(cache, std::ios::in | std::ios::out | std::ios::binary);
    const std::uint64_t huge = std::uint64_t{1} << 62;
    header.seekp(32);
    header.write(reinterpret_cast<const char*>(&huge), sizeof huge);
    header.close();
    EXPECT_NE(readError(cache).find("is truncated"), std::string::npos) << readError(cache);

    // Beyond any cache's size: refused before the header is even read.
    fs::resize_file(notCache, (std::uintmax_t{1} << 36) + 1);
    EXPECT_EQ(readError(notCache), notCache.string() +
                                       ": 68719476737 bytes is too large for a cache file (at most "
                                       "64 GiB); is it the right file?");
}

TEST(CacheFileTest, FoldersAndDevicesAreRefusedByName) {
    const TestFolder folder;
    EXPECT_EQ(readError(folder.path()),
              folder.path().string() + ": is a directory, not a cache file");
    EXPECT_EQ(readError("/dev/zero"), "/dev/zero: is a character device, not a cache file");
    EXPECT_THROW(readCacheKeyHash(folder.path()), Error);
    EXPECT_EQ(readError(folder / "missing.mfbasis"),
              (folder / "missing.mfbasis").string() + ": no such cache file");
}

/// A basis changed by `damage`, written with a valid checksum: only the consistency checks can
/// tell it from a real one.
std::string errorOfDamaged(const std::function<void(BasisCache&)>& damage) {
    const TestFolder folder;
    BasisCache cache = smallBasis();
    damage(cache);
    writeCache(folder / "damaged.mfbasis", cache);
    return readError(folder / "damaged.mfbasis");
}

TEST(CacheFileTest, AWellFormedButInconsistentBasisIsRefused) {
    EXPECT_NE(errorOfDamaged([](BasisCache& c) { c.faces[0] = 1'000'000'000; })
                  .find("is corrupt (its face degrees of freedom disagree with the grid or the "
                        "velocity modes)"),
              std::string::npos);
    EXPECT_NE(
        errorOfDamaged([](BasisCache& c) { c.faces.pop_back(); }).find("face degrees of freedom"),
        std::string::npos);
    EXPECT_NE(errorOfDamaged([](BasisCache& c) {
                  c.grid.dim = 5;
              }).find("its grid is not a 2D or 3D grid"),
              std::string::npos);
    EXPECT_NE(
        errorOfDamaged([](BasisCache& c) { c.grid.resolution[0] = -8; }).find("its grid is not"),
        std::string::npos);
    EXPECT_NE(errorOfDamaged([](BasisCache& c) { c.wall = WallKind(7); }).find("a choice"),
              std::string::npos);
    EXPECT_NE(
        errorOfDamaged([](BasisCache& c) { c.cells.back() = -1; }).find("cell degrees of freedom"),
        std::string::npos);
    EXPECT_NE(errorOfDamaged([](BasisCache& c) {
                  c.velocity.eigenvalues.resize(1);
              }).find("velocity eigenvalues"),
              std::string::npos);
    EXPECT_NE(errorOfDamaged([](BasisCache& c) {
                  c.coefficients.packed.pop_back();
              }).find("dense coefficients"),
              std::string::npos);
    EXPECT_NE(errorOfDamaged([](BasisCache& c) {
                  c.grid.boundsMax[1] = std::nan("");
              }).find("grid bounds"),
              std::string::npos);
    EXPECT_EQ(errorOfDamaged([](BasisCache&) {}), "accepted") << "the undamaged basis";
}

TEST(CacheFileTest, AnEarlierFormatIsRefusedByItsVersion) {
    // Format 6 added the vorticity quadrature: a format-5 file (same magic) must be rebuilt.
    const TestFolder folder;
    const fs::path file = folder / "old.mfbasis";
    writeCache(file, smallBasis());
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        const std::uint32_t previous = kCacheFormatVersion - 1;
        f.seekp(16);  // after the magic
        f.write(reinterpret_cast<const char*>(&previous), sizeof previous);
    }
    const std::string message = readError(file);
    EXPECT_NE(message.find("has format version " + std::to_string(kCacheFormatVersion - 1) +
                           ", this modeflow reads version " + std::to_string(kCacheFormatVersion)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("rerun precompute"), std::string::npos) << message;
}

TEST(CacheFileTest, TheQuadratureAndAMissingTensorRoundTrip) {
    const TestFolder folder;
    BasisCache cache = smallBasis();
    ASSERT_GT(cache.quadrature.curl.rows(), 0);
    cache.coefficients = BasisCache::Coefficients{};
    cache.coefficients.storage = BasisCache::Coefficients::Storage::None;
    writeCache(folder / "free.mfbasis", cache);
    const BasisCache read = readCache(folder / "free.mfbasis");
    EXPECT_EQ(read.coefficients.storage, BasisCache::Coefficients::Storage::None);
    for (const auto& [got, want] :
         {std::pair{&read.quadrature.curl, &cache.quadrature.curl},
          std::pair{&read.quadrature.velocityB, &cache.quadrature.velocityB},
          std::pair{&read.quadrature.velocityC, &cache.quadrature.velocityC}}) {
        EXPECT_EQ(got->start, want->start);
        EXPECT_EQ(got->column, want->column);
        EXPECT_EQ(got->value, want->value);
    }
}

TEST(CacheFileTest, AQuadratureOrStorageThatDoesNotFitIsRefused) {
    const auto quadrature = [](const std::function<void(BasisCache&)>& damage) {
        return errorOfDamaged(damage).find("its vorticity quadrature is not three maps") !=
               std::string::npos;
    };
    EXPECT_TRUE(quadrature([](BasisCache& c) {
        c.quadrature.velocityB.column.front() = std::int32_t(c.faces.size());
    }));
    EXPECT_TRUE(quadrature([](BasisCache& c) {
        SparseRows& m = c.quadrature.velocityC;
        m.start.pop_back();
        m.column.resize(std::size_t(m.start.back()));
        m.value.resize(m.column.size());
    }));
    EXPECT_TRUE(quadrature(
        [](BasisCache& c) { c.quadrature.curl.start[1] = c.quadrature.curl.start[2] + 1; }));
    const auto windFlows = [](const std::function<void(BasisCache&)>& damage) {
        return errorOfDamaged(damage).find(
                   "its wind base flows are not one finite face field per axis and direction") !=
               std::string::npos;
    };
    EXPECT_TRUE(windFlows([](BasisCache& c) { c.windBase.pop_back(); }));
    EXPECT_TRUE(windFlows([](BasisCache& c) { c.windBase[1].pop_back(); }));
    EXPECT_TRUE(windFlows([](BasisCache& c) { c.windBase[0][3] = std::nan(""); }));
    EXPECT_TRUE(windFlows([](BasisCache& c) { c.windStokes.pop_back(); }));
    EXPECT_TRUE(windFlows([](BasisCache& c) { c.windStokes[2].pop_back(); }));
    EXPECT_TRUE(windFlows([](BasisCache& c) { c.windStokes[1][0] = std::nan(""); }));
    EXPECT_NE(errorOfDamaged([](BasisCache& c) {
                  c.coefficients.storage = BasisCache::Coefficients::Storage(7);
              }).find("coefficient storage"),
              std::string::npos);
    EXPECT_NE(errorOfDamaged([](BasisCache& c) {
                  c.coefficients.storage = BasisCache::Coefficients::Storage::None;
              }).find("storage says none"),
              std::string::npos);
}

}  // namespace
}  // namespace modeflow
