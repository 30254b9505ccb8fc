/// A surface basis in a cache file: it reads back whole, and a surface block whose indices or
/// sizes do not fit the rest (or a grid's vorticity quadrature, or no coefficients) is refused as
/// corrupt, never misread.

#include <gtest/gtest.h>

#include <string>

#include "engine/core/Error.h"
#include "engine/format/CacheFile.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

BasisCache torusCache(const testing::TestFolder& folder) {
    writeObj(folder / "torus.obj", makeTorus(16, 8, 1.0, 0.4));
    SceneSpec scene;
    scene.surface = SurfaceSpec{folder / "torus.obj"};
    scene.basis.velocityModes = {{1, 6}};
    scene.basis.scalarModes = 4;
    Progress quiet = Progress::silent();
    BasisCache cache = computeBasis(scene, quiet);
    cache.key = basisKey(scene);
    return cache;
}

std::string readError(const std::filesystem::path& path) {
    try {
        readCache(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(SurfaceCache, RoundTripsTheMeshEdgesAndBases) {
    testing::TestFolder folder;
    const BasisCache cache = torusCache(folder);
    writeCache(folder / "torus.mfbasis", cache);
    const BasisCache back = readCache(folder / "torus.mfbasis");
    EXPECT_EQ(back.kind, BasisKind::Surface);
    EXPECT_EQ(back.surface.mesh, cache.surface.mesh);
    EXPECT_EQ(back.surface.edges, cache.surface.edges);
    EXPECT_EQ(back.velocity.modes, cache.velocity.modes);
    EXPECT_EQ(back.velocity.harmonic, 2);
    EXPECT_EQ(back.scalar.modes, cache.scalar.modes);
    EXPECT_EQ(back.coefficients.packed, cache.coefficients.packed);
    EXPECT_EQ(back.key, cache.key);
}

TEST(SurfaceCache, RefusesASurfaceBlockThatDoesNotFit) {
    testing::TestFolder folder;
    const BasisCache good = torusCache(folder);
    BasisCache bad = good;
    bad.surface.mesh.triangles[3][1] = int(bad.surface.mesh.vertices.size());
    writeCache(folder / "index.mfbasis", bad);
    EXPECT_NE(readError(folder / "index.mfbasis").find("is corrupt"), std::string::npos);
    bad = good;
    bad.surface.edges.pop_back();
    writeCache(folder / "edges.mfbasis", bad);
    EXPECT_NE(readError(folder / "edges.mfbasis").find("is corrupt"), std::string::npos);
}

TEST(SurfaceCache, RefusesAQuadratureWindFlowsOrMissingCoefficients) {
    testing::TestFolder folder;
    const BasisCache good = torusCache(folder);
    ASSERT_EQ(good.quadrature.curl.rows(), 0);
    ASSERT_NE(good.coefficients.storage, BasisCache::Coefficients::Storage::None);
    const std::string refusal = "holds a vorticity quadrature, wind base flows or no coefficients";
    const auto expectRefused = [&](const char* name, const BasisCache& bad) {
        writeCache(folder / name, bad);
        EXPECT_NE(readError(folder / name).find(refusal), std::string::npos)
            << readError(folder / name);
    };
    BasisCache bad = good;
    bad.quadrature.curl.start.push_back(0);  // one element without entries
    bad.quadrature.velocityB.start.push_back(0);
    bad.quadrature.velocityC.start.push_back(0);
    expectRefused("quadrature.mfbasis", bad);
    bad = good;
    bad.coefficients = BasisCache::Coefficients{};
    bad.coefficients.storage = BasisCache::Coefficients::Storage::None;
    expectRefused("none.mfbasis", bad);
    bad = good;
    bad.windBase.assign(3, std::vector<double>(4, 1.0));  // a surface has no sides to blow at
    expectRefused("wind.mfbasis", bad);
}

}  // namespace
}  // namespace modeflow
