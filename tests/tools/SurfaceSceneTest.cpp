/// Surface scenes through the `modeflow` binary: a mesh that is not a closed surface is refused
/// at precompute naming [surface].mesh and the problem, inspect reports the surface and its
/// harmonic modes, run writes PLY frames and pictures on either backend (the device's resumed
/// bit for bit), and half floats are refused.

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

TEST_F(SurfaceScene, HalfFloatFramesAreRefusedBeforeAnyWork) {
    writeObj(mDir / "sphere.obj", makeIcosphere(1));
    const fs::path s = surfaceScene("sphere.obj");
    expectRejected("run " + s.string() + " --device cpu --half --out " + (mDir / "o").string() +
                       " --cache-dir " + mCache.string(),
                   "--half: surface scenes write PLY frames");
    EXPECT_FALSE(fs::exists(mCache) && !fs::is_empty(mCache)) << "a cache was written first";
}

TEST_F(SurfaceScene, RunsOnTheDeviceAndResumesBitForBit) {
    writeObj(mDir / "sphere.obj", makeIcosphere(2));
    const fs::path s =
        surfaceScene("sphere.obj",
                     "[initial]\nvelocity = \"random\"\n[[source]]\nshape = \"ball\"\n"
                     "center = [0.0, 0.0, 1.0]\nradius = 0.4\ndensity = 1.0\n");
    const auto simulate = [&](const fs::path& out, int frames, const std::string& extra) {
        return run("run " + s.string() + " --device vulkan --frames " + std::to_string(frames) +
                   " --out " + out.string() + " --cache-dir " + mCache.string() + extra);
    };
    const RunResult whole = simulate(mDir / "whole", 6, "");
    ASSERT_EQ(whole.status, 0) << whole.err;
    EXPECT_NE(whole.err.find("Vulkan device"), std::string::npos) << whole.err;
    ASSERT_EQ(simulate(mDir / "parts", 3, "").status, 0);
    const RunResult resumed = simulate(mDir / "parts", 6, " --resume");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    const std::string last = slurp(mDir / "whole" / "surface_0006.ply");
    EXPECT_GT(last.size(), 1000u);
    EXPECT_EQ(slurp(mDir / "parts" / "surface_0006.ply"), last) << "the resumed run's last frame";
    // The CPU reference's run of the same scene is another run (its own resume point), and its
    // frames differ from the device's in float32's last digits only (checked on the states by
    // SurfaceDeviceTest).
    const RunResult cpu =
        run("run " + s.string() + " --device cpu --frames 6 --out " + (mDir / "parts").string() +
            " --cache-dir " + mCache.string() + " --resume");
    EXPECT_NE(cpu.status, 0) << "a device run's checkpoint resumed on the CPU";
    EXPECT_NE(cpu.err.find("written for another scene text, basis (mesh file) or device"),
              std::string::npos)
        << cpu.err;
}

}  // namespace
}  // namespace modeflow::testing
