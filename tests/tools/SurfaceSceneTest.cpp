/// Surface scenes through the `modeflow` binary: a mesh that is not a closed surface is refused
/// at precompute naming [surface].mesh and the problem, inspect reports the surface and its
/// harmonic modes, run writes PLY frames and pictures, and what surfaces do not do is refused.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/CliFixture.h"

namespace modeflow::testing {
namespace {

class SurfaceScene : public Cli {
protected:
    fs::path surfaceScene(const std::string& mesh, const std::string& extra = "") const {
        return scene("surface.toml", "[surface]\nmesh = \"" + mesh +
                                         "\"\n[basis]\nvelocity_modes = 6\nscalar_modes = 6\n" +
                                         extra);
    }
};

TEST_F(SurfaceScene, AnOpenMeshIsRefusedNamingTheKeyAndTheEdge) {
    TriangleMesh open = makeIcosphere(1);
    open.triangles.pop_back();
    writeObj(mDir / "open.obj", open);
    expectRejected(precompute(surfaceScene("open.obj")), "[surface].mesh: mesh file " +
                                                             (mDir / "open.obj").string() +
                                                             ": the surface is not closed");
}

TEST_F(SurfaceScene, InspectReportsTheSurfaceAndItsHarmonicModes) {
    writeObj(mDir / "torus.obj", makeTorus(24, 10, 1.0, 0.4));
    const RunResult r = run("inspect " + surfaceScene("torus.obj").string() +
                            " --json --cache-dir " + mCache.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["kind"], "surface");
    EXPECT_EQ(j["surface"]["vertices"], 240);
    EXPECT_EQ(j["velocity"]["harmonic"], 2);
    EXPECT_LT(j["velocity"]["max_divergence"].get<double>(), 1e-13);
    EXPECT_LT(j["velocity"]["orthonormality_error"].get<double>(), 1e-10);
}

TEST_F(SurfaceScene, RunWritesPlyFramesPicturesAndAContactSheet) {
    writeObj(mDir / "sphere.obj", makeIcosphere(2));
    const fs::path s =
        surfaceScene("sphere.obj",
                     "[initial]\nvelocity = \"random\"\n[[source]]\nshape = \"ball\"\n"
                     "center = [0, 0, 1]\nradius = 0.4\n");
    const fs::path out = mDir / "frames";
    const RunResult r =
        run("run " + s.string() + " --device cpu --frames 4 --preview-every 2 --out " +
            out.string() + " --cache-dir " + mCache.string());
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* file : {"surface_0001.ply", "surface_0004.ply", "surface_0002.png",
                             "surface_0004.png", "surface_contact.png", "surface.resume"})
        EXPECT_TRUE(fs::exists(out / file)) << file;
    EXPECT_FALSE(fs::exists(out / "surface_0001.png"));
}

TEST_F(SurfaceScene, WhatSurfacesDoNotDoIsRefusedBeforeAnyWork) {
    writeObj(mDir / "sphere.obj", makeIcosphere(1));
    const fs::path s = surfaceScene("sphere.obj");
    expectRejected("run " + s.string() + " --device cpu --half --out " + (mDir / "o").string() +
                       " --cache-dir " + mCache.string(),
                   "--half: surface scenes write PLY frames");
    expectRejected("run " + s.string() + " --device vulkan --out " + (mDir / "o").string() +
                       " --cache-dir " + mCache.string(),
                   "[surface] scenes run on the CPU reference only; use --device cpu");
    // The window shows on a Vulkan device, but the surface's flow runs on the CPU: a device to
    // simulate on is refused through the backends' table, before the precompute.
    for (const std::string device : {"0", "vulkan"})
        expectRejected("stir " + s.string() + " --device " + device + " --frames 1 --cache-dir " +
                           mCache.string(),
                       s.string() +
                           ": [surface] scenes run on the CPU reference only; use "
                           "--device cpu");
    EXPECT_FALSE(fs::exists(mCache) && !fs::is_empty(mCache)) << "a cache was written first";
}

}  // namespace
}  // namespace modeflow::testing
