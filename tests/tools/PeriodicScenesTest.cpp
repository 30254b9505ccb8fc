/// @file PeriodicScenesTest.cpp
/// The shipped periodic scenes run end to end with the real `modeflow` binary on both backends:
/// within a few frames their smoke has crossed a seam (it shows at the far end of a periodic
/// axis, where no source emits and nothing but the wrap could have carried it), and their VDB
/// frames say which axes wrap.

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/MacGrid.h"
#include "engine/output/VdbFrame.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

struct PeriodicScene {
    const char* file;       ///< under scenes/
    int frames;             ///< enough for the smoke to cross the seam
    int axis;               ///< the periodic axis the smoke crosses
    double farFrom, farTo;  ///< where along it only smoke that wrapped can be
};

/// The channel's source sits at x = 1.75 and the paddle pushes its smoke along +x through the
/// seam at x = 2 (= 0); the torus's warm smoke rises from z = 0.9 through the top at z = 1.5
/// and comes back in at the bottom.
const PeriodicScene kScenes[] = {{"periodic_channel_2d.toml", 16, 0, 0.0, 0.25},
                                 {"torus_box_3d.toml", 24, 2, -1.5, -1.2}};

class PeriodicScenes : public Cli, public ::testing::WithParamInterface<PeriodicScene> {};

TEST_P(PeriodicScenes, SmokeCrossesTheSeamAndTheFramesSayWhichAxesWrap) {
    const PeriodicScene& p = GetParam();
    const fs::path file = fs::path(MODEFLOW_SOURCE_DIR) / "scenes" / p.file;
    const SceneSpec scene = loadScene(file);
    ASSERT_TRUE(scene.grid.isPeriodic(p.axis));
    const MacGrid smoke = MacGrid::fromSpec(scene.grid).refined(scene.smoke.resolutionScale);
    std::vector<Vec3> far;
    for (int z = 0; z < smoke.cells[2]; ++z)
        for (int y = 0; y < smoke.cells[1]; ++y)
            for (int x = 0; x < smoke.cells[0]; ++x) {
                const Vec3 c{smoke.cellCentre(0, x), smoke.cellCentre(1, y),
                             smoke.dim == 3 ? smoke.cellCentre(2, z) : 0.0};
                if (c[p.axis] > p.farFrom && c[p.axis] < p.farTo) far.push_back(c);
            }
    for (const std::string backend : {"cpu", "vulkan"}) {
        SCOPED_TRACE(backend);
        const fs::path out = mDir / backend;
        const RunResult r =
            run("run " + file.string() + " --frames " + std::to_string(p.frames) + " --device " +
                backend + " --out " + out.string() + " --cache-dir " + mCache.string());
        ASSERT_EQ(r.status, 0) << r.err;
        const fs::path last = out / frameFileName(scene.name, p.frames);
        const VdbFrameInfo info = readVdbFrameInfo(last);
        ASSERT_TRUE(info.periodic.has_value()) << "no modeflow_periodic metadata in " << last;
        EXPECT_EQ(*info.periodic, scene.grid.periodic);
        for (const VdbGridInfo& g : info.grids) EXPECT_EQ(g.periodic, info.periodic) << g.name;
        EXPECT_NEAR(info.grid("density")->voxelSize[0], smoke.spacing[0], 1e-12)
            << "the documented lattice";
        // The first frame has no smoke at the far end yet; the last has.
        const auto smokeAtFarEnd = [&](const fs::path& vdb) {
            double most = 0.0;
            for (const VdbSample& s : sampleVdbGrid(vdb, "density", far))
                most = std::max(most, s.value[0]);
            return most;
        };
        const double before = smokeAtFarEnd(out / frameFileName(scene.name, 1));
        const double after = smokeAtFarEnd(last);
        std::cout << p.file << " on " << backend
                  << ": most smoke at the far end of the seam, frame 1 " << before << ", frame "
                  << p.frames << " " << after << "\n";
        EXPECT_EQ(before, 0.0);
        EXPECT_GT(after, 0.05);
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, PeriodicScenes, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<PeriodicScene>& info) {
                             return fs::path(info.param.file).stem().string();
                         });

}  // namespace
}  // namespace modeflow
