/// Every scene under scenes/ runs end to end with the real `modeflow` binary, one test per scene
/// (named after it), found when the test runs: `run --frames 2` on each backend (the frames read
/// back: VDB files, or PLY files for surface scenes; the resume checkpoint holds a finite state,
/// moving when the scene sets anything going), and `modes` for a few steps (finite energy).
/// tests/CMakeLists.txt rebuilds this test when a scene file is added or removed, so that CTest's
/// list follows scenes/.
///
/// A scene whose precompute is long (velocity DOFs × highest mode above 4e6, see
/// tests/support/ShippedScenes.h) runs on a reduced copy, and the test prints what it ran. When
/// this was written (factor of the resolution per axis and of the modes):
///   bench/ball_48                    [48³], 100 modes         → [23³], 48 modes          (0.48)
///   bench/ball_64                    [64³], 200 modes         → [20³], 63 modes          (0.31)
///   bench/disk_256                   [256²], 100 + 50 scalar  → [122²], 48 + 24 scalar   (0.48)
///   box_3d                           [32³], 50 + 20 scalar    → [21³], 33 + 13 scalar    (0.66)
///   seed/hot_blob_mesh_3d            [40³], 120 modes         → [24³], 71 modes          (0.59)
///   seed/smoke_past_sphere_3d        [32,32,48], 230 modes    → [12,12,19], 89 modes     (0.39)
///   seed/smoke_past_sphere_shaped_3d [32,32,48], 1-115,516-630 → [10,10,15], 1-36,163-198 (0.31)
///   sphere_obstacle_3d               [32,32,48], 60 + 20 scalar → [17,17,26], 32 + 11 scalar
///   (0.53) stir_3d                          [32³], 100 modes         → [21³], 66 modes (0.66)
/// The other scenes (all 2D ones but disk_256, and torus_3d) run as shipped.

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/output/PlyFrame.h"
#include "engine/output/VdbFrame.h"
#include "engine/simulation/Checkpoint.h"
#include "tests/support/CliFixture.h"
#include "tests/support/ShippedScenes.h"

namespace modeflow::testing {
namespace {

constexpr int kFrames = 2;
constexpr int kModeSteps = 4;

bool allFinite(const Eigen::VectorXd& v) {
    return v.allFinite();
}

bool allFinite(const std::vector<double>& values) {
    for (double x : values)
        if (!std::isfinite(x)) return false;
    return true;
}

class ShippedScene : public Cli, public ::testing::WithParamInterface<fs::path> {
protected:
    /// `run` on `backend`: the frames exist and read back, the checkpoint is finite and moving.
    void runs(const SceneUnderTest& s, const std::string& backend) {
        const fs::path out = mDir / ("frames_" + backend);
        const RunResult r =
            run("run " + s.file.string() + " --frames " + std::to_string(kFrames) + " --device " +
                backend + " --out " + out.string() + " --cache-dir " + mCache.string());
        ASSERT_EQ(r.status, 0) << "run --device " << backend << ": " << r.err;
        for (int frame = 1; frame <= kFrames && s.scene.isSurface(); ++frame) {
            // A surface scene's frames are PLY files: a header for its mesh, the binary data after
            // it.
            const fs::path ply = out / plyFrameFileName(s.scene.name, frame);
            ASSERT_TRUE(fs::exists(ply)) << ply;
            const std::string text = slurp(ply);
            EXPECT_EQ(text.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << ply;
            EXPECT_NE(text.find("comment frame " + std::to_string(frame) + "\n"), std::string::npos)
                << ply;
            EXPECT_NE(text.find("property float density\n"), std::string::npos) << ply;
        }
        for (int frame = 1; frame <= kFrames && !s.scene.isSurface(); ++frame) {
            const fs::path vdb = out / frameFileName(s.scene.name, frame);
            ASSERT_TRUE(fs::exists(vdb)) << vdb;
            EXPECT_GT(fs::file_size(vdb), 0u) << vdb;
            const VdbFrameInfo info = readVdbFrameInfo(vdb);
            EXPECT_EQ(info.frame, frame) << vdb;
            EXPECT_NE(info.grid("density"), nullptr) << vdb;
            EXPECT_NE(info.grid("vel"), nullptr) << vdb;
        }
        const Checkpoint c = readCheckpoint(out / (s.scene.name + ".resume"));
        EXPECT_EQ(c.frame, kFrames);
        EXPECT_TRUE(allFinite(c.velocity)) << "velocity on " << backend;
        EXPECT_TRUE(allFinite(c.magnetic)) << "magnetic field on " << backend;
        EXPECT_TRUE(allFinite(c.smoke.density)) << "density on " << backend;
        EXPECT_TRUE(allFinite(c.smoke.temperature)) << "temperature on " << backend;
        // What the scene sets going shows: the fluid moves, or smoke is there. (The precompute
        // benchmarks in scenes/bench/ set nothing going and stay still.)
        const bool setsGoing = s.scene.initial.velocity != InitialVelocity::Zero ||
                               !s.scene.sources.empty() || !s.scene.obstacles.empty();
        double smoke = 0.0;
        for (double d : c.smoke.density) smoke += d;
        if (setsGoing) {
            EXPECT_GT(c.velocity.squaredNorm() + smoke, 0.0)
                << "nothing moves and no smoke after " << kFrames << " frames on " << backend;
        }
    }

    /// `modes` on `backend` for a few steps: every energy of the CSV is finite.
    void stepsModes(const SceneUnderTest& s, const std::string& backend) {
        const RunResult r =
            run("modes " + s.file.string() + " --csv --steps " + std::to_string(kModeSteps) +
                " --device " + backend + " --cache-dir " + mCache.string());
        ASSERT_EQ(r.status, 0) << "modes --device " << backend << ": " << r.err;
        std::istringstream csv(r.out);
        std::string row;
        std::getline(csv, row);
        ASSERT_EQ(row.rfind("step,time,energy,", 0), 0u) << r.out;
        int rows = 0;
        while (std::getline(csv, row)) {
            std::istringstream fields(row);
            std::string step, time, energy;
            std::getline(fields, step, ',');
            std::getline(fields, time, ',');
            std::getline(fields, energy, ',');
            EXPECT_TRUE(std::isfinite(std::stod(energy)))
                << "modes --device " << backend << ": " << row;
            ++rows;
        }
        EXPECT_EQ(rows, kModeSteps + 1) << r.out;
    }
};

TEST_P(ShippedScene, RunsEndToEnd) {
    const SceneUnderTest s = sceneUnderTest(GetParam(), mDir / "reduced");
    std::cout << s.description << "\n";
    RecordProperty("scene", s.description);
    for (const std::string& backend : backendOptions()) {
        runs(s, backend);
        stepsModes(s, backend);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene, ::testing::ValuesIn(shippedScenes()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                             return sceneTestName(info.param);
                         });

TEST(ShippedScenes, AreFoundUnderScenes) {
    const std::vector<fs::path> scenes = shippedScenes();
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), fs::path("default.toml")), scenes.end());
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), fs::path("seed/smoke_past_sphere_3d.toml")),
              scenes.end());
}

}  // namespace
}  // namespace modeflow::testing
