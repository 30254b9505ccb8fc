/// @file RunCommandTest.cpp
/// `modeflow run`: a scene in, OpenVDB frames out (read back with OpenVDB), resumable, and bad
/// input refused before any work.

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include "engine/core/MacGrid.h"
#include "engine/output/RunFolder.h"
#include "engine/output/VdbFrame.h"
#include "engine/simulation/Checkpoint.h"
#include "tests/support/CliFixture.h"
#include "tests/support/PngFile.h"
#include "tests/support/Sanitizers.h"
#include "tests/support/SceneFixtures.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

const std::string kHotDisk = std::string(testing::kSmallDisk) + R"(
[simulation]
dt = 0.02
[initial]
velocity = "random"
energy = 0.05
seed = 3
[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.25
density = 2.0
temperature = 1.0
[smoke]
buoyancy = 1.0
resolution_scale = 2
[[particles]]
shape = "ball"
center = [0.0, 0.3]
radius = 0.3
count = 200
[[particles]]
shape = "box"
min = [-0.5, -0.2]
max = [0.5, 0.2]
rate = 500
drag = 2
gravity = 1
[output]
frames = 4
steps_per_frame = 2
)";

/// A rotor in a uniform magnetic field (seed Fig. 6.18) on the small disk.
const std::string kMhdRotor = std::string(testing::kSmallDisk) + R"(
[simulation]
dt = 0.02
mhd = true
magnetic_diffusivity = 0.01
[initial]
velocity = "vortices"
magnetic = "uniform"
magnetic_direction = [1, 0]
magnetic_strength = 0.5
[[initial.vortex]]
center = [0.0, 0.0]
strength = 2.0
radius = 0.3
[[source]]
shape = "box"
min = [-0.4, -0.1]
max = [0.4, 0.1]
density = 20.0
end = 0.05
[smoke]
resolution_scale = 2
[output]
frames = 4
steps_per_frame = 2
)";

/// Every smoke cell centre of the scene's 48² smoke grid, z = 0.
std::vector<Vec3> smokeCentres() {
    GridSpec spec;
    spec.dim = 2;
    spec.resolution = {24, 24, 1};
    spec.boundsMin = {-1.1, -1.1, 0.0};
    spec.boundsMax = {1.1, 1.1, 0.0};
    const MacGrid grid = MacGrid::fromSpec(spec).refined(2);
    std::vector<Vec3> centres;
    for (int y = 0; y < grid.cells[1]; ++y)
        for (int x = 0; x < grid.cells[0]; ++x)
            centres.push_back({grid.cellCentre(0, x), grid.cellCentre(1, y), 0.0});
    return centres;
}

class RunCommand : public Cli {
protected:
    RunResult simulate(const fs::path& scene, const fs::path& out,
                       const std::string& extra = "") const {
        return run("run " + scene.string() + " --out " + out.string() + " --cache-dir " +
                   mCache.string() + " " + extra);
    }
};

TEST_F(RunCommand, ADeformingObstacleReadsTheFilesAsFarAsFramesGoes) {
    // A closed-form box with a tetrahedron deforming over numbered files, ten a unit of time:
    // `--frames 4` (to t = 0.08) shows file 1 and runs with files 1 and 2 alone; `--frames 10`
    // (to t = 0.2) shows file 3, refused naming it before any frame while it is missing.
    const auto tetrahedron = [&](int number, double shift) {
        std::ofstream(mDir / ("tet_000" + std::to_string(number) + ".obj"))
            << "v " << shift << " 0 0\nv " << 1 + shift << " 0 0\nv " << shift << " 1 0\nv "
            << shift << " 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    };
    tetrahedron(1, 0.0);
    tetrahedron(2, 0.1);
    const fs::path s = scene("tet.toml", R"([grid]
resolution = [12, 12, 12]
bounds_min = [0, 0, 0]
bounds_max = [1, 1, 1]
[basis]
velocity_modes = 40
scalar_modes = 0
wall = "free-slip"
[simulation]
dt = 0.02
[[source]]
shape = "ball"
center = [0.5, 0.5, 0.2]
radius = 0.15
density = 1.0
[[obstacle]]
shape = "mesh"
file = "tet_####.obj"
sequence_rate = 10
scale = 0.3
path = [[0.0, 0.4, 0.4, 0.4]]
[output]
frames = 4
steps_per_frame = 1
)");
    RunResult r = simulate(s, mDir / "short", "--frames 4 --device cpu");
    EXPECT_EQ(r.status, 0) << r.err;
    r = simulate(s, mDir / "long", "--frames 10 --device cpu");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("tet_0003.obj is missing"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(mDir / "long" / frameFileName("tet", 1)));
    tetrahedron(3, 0.2);
    r = simulate(s, mDir / "long", "--frames 10 --device cpu");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(mDir / "long" / frameFileName("tet", 10)));
}

TEST_F(RunCommand, WritesVdbFramesThatReadBack) {
    const fs::path s = scene("hot.toml", kHotDisk), out = mDir / "frames";
    const RunResult r = simulate(s, out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("Vulkan device:"), std::string::npos)
        << "the run must say which device runs";
    EXPECT_EQ(r.out, out.string() + "\n") << "stdout's last line is the output folder";
    for (int frame = 1; frame <= 4; ++frame)
        EXPECT_TRUE(fs::exists(out / frameFileName("hot", frame))) << frame;

    const VdbFrameInfo info = readVdbFrameInfo(out / "hot_0003.vdb");
    ASSERT_NE(info.grid("density"), nullptr);
    ASSERT_NE(info.grid("temperature"), nullptr);
    ASSERT_NE(info.grid("vel"), nullptr);
    EXPECT_EQ(info.grid("density")->gridClass, "fog volume");
    EXPECT_EQ(info.grid("vel")->valueType, "vec3s");
    EXPECT_EQ(info.frame, 3);
    EXPECT_NEAR(*info.time, 3 * 2 * 0.02, 1e-12);
    EXPECT_EQ(info.creator, "modeflow");
    EXPECT_NEAR(info.grid("density")->voxelSize[0], 2.2 / 48, 1e-12);
    // The particles' point clouds: the 200 tracers and 500/s × 2 steps of 0.02 a frame.
    for (int frame = 1; frame <= 4; ++frame) {
        const std::string cloud =
            testing::slurp(out / ("hot_particles_000" + std::to_string(frame) + ".ply"));
        EXPECT_NE(cloud.find("element vertex " + std::to_string(200 + 20 * frame) + "\n"),
                  std::string::npos)
            << frame;
    }

    // Smoke inside the disk only; none outside it (half a basis cell of slack for cut cells).
    const std::vector<Vec3> centres = smokeCentres();
    const std::vector<VdbSample> density = sampleVdbGrid(out / "hot_0003.vdb", "density", centres);
    int inside = 0;
    for (std::size_t c = 0; c < centres.size(); ++c) {
        const double r2 = centres[c][0] * centres[c][0] + centres[c][1] * centres[c][1];
        if (r2 > std::pow(1.0 + 0.05, 2)) {
            EXPECT_FALSE(density[c].active) << "smoke outside the domain at " << c;
        }
        inside += density[c].active;
    }
    EXPECT_GT(inside, 20);
}

/// kHotDisk with `integrator` (the scene's default, midpoint, when empty).
std::string hotDisk(const std::string& integrator) {
    if (integrator.empty()) return kHotDisk;
    std::string text = kHotDisk;
    const std::string dt = "dt = 0.02\n";
    return text.replace(text.find(dt), dt.size(), dt + "integrator = \"" + integrator + "\"\n");
}

TEST_F(RunCommand, ResumeGivesTheFramesOfAnUninterruptedRun) {
    // Every integrator on the device, stopped after the first frame and after the third; the
    // midpoint rule and the linearized rule on the CPU too.
    struct Case {
        std::string integrator, device;
    };
    std::vector<Case> cases;
    for (const std::string integrator : {"", "explicit", "rk4", "trapezoidal", "linearized"})
        cases.push_back({integrator, ""});
    for (const std::string integrator : {"", "linearized"}) cases.push_back({integrator, "cpu"});
    for (const Case& c : cases) {
        const std::string name = (c.integrator.empty() ? "midpoint" : c.integrator) +
                                 (c.device.empty() ? "" : "_" + c.device);
        const std::string device = c.device.empty() ? "" : " --device " + c.device;
        const fs::path s = scene("hot.toml", hotDisk(c.integrator));
        const fs::path whole = mDir / ("whole" + name);
        ASSERT_EQ(simulate(s, whole, device).status, 0);
        for (const int stop : {1, 3}) {
            const fs::path parts = mDir / ("parts" + name + std::to_string(stop));
            // A run stopped after frame `stop` (the checkpoint is written after every frame).
            ASSERT_EQ(simulate(s, parts, device + " --frames " + std::to_string(stop)).status, 0);
            const StepCarry carry = readCheckpoint(parts / "hot.resume").carry;
            // The linearized rule's checkpoint carries the rate its next predictor starts from,
            // the device midpoint rule's the right-hand sides its next iteration starts from.
            EXPECT_EQ(carry.heldRate.size(), c.integrator == "linearized" ? 8 : 0) << name;
            EXPECT_EQ(carry.warmRhs.size(), c.integrator.empty() && c.device.empty() ? 2u : 0u)
                << name;
            const RunResult resumed = simulate(s, parts, device + " --resume");
            ASSERT_EQ(resumed.status, 0) << resumed.err;
            EXPECT_NE(resumed.err.find("resuming after frame " + std::to_string(stop)),
                      std::string::npos)
                << resumed.err;
            // The last checkpoints are the same bytes: state, smoke and what the steps carry (a
            // cold first step after the resume can reach the same state, not the same carry).
            EXPECT_EQ(testing::slurp(parts / "hot.resume"), testing::slurp(whole / "hot.resume"))
                << name << ", resumed after " << stop;
            const std::vector<Vec3> centres = smokeCentres();
            for (int frame = stop + 1; frame <= 4; ++frame) {
                const std::string file = frameFileName("hot", frame);
                const std::string cloud = "hot_particles_000" + std::to_string(frame) + ".ply";
                EXPECT_EQ(testing::slurp(parts / cloud), testing::slurp(whole / cloud))
                    << name << ", resumed after " << stop << ": " << cloud;
                for (const char* grid : {"density", "temperature", "vel"}) {
                    const auto a = sampleVdbGrid(whole / file, grid, centres);
                    const auto b = sampleVdbGrid(parts / file, grid, centres);
                    for (std::size_t cell = 0; cell < centres.size(); ++cell)
                        ASSERT_EQ(a[cell].value, b[cell].value)
                            << name << ", resumed after " << stop << ": " << file << " " << grid
                            << " cell " << cell;
                }
            }
        }
    }
    // The checkpoint belongs to the scene text it was written for.
    const fs::path changed = scene("hot.toml", std::string(kHotDisk) + "# edited\n");
    const RunResult refused = simulate(changed, mDir / "partsmidpoint1", "--resume");
    EXPECT_NE(refused.status, 0);
    EXPECT_NE(refused.err.find("another scene"), std::string::npos) << refused.err;
}

/// A hot torch on the small disk burning its fuel: the flame rises with the hot air.
const std::string kTorch = std::string(testing::kSmallDisk) + R"(
[simulation]
dt = 0.02
[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.2
density = 0.5
temperature = 4.0
fuel = 6.0
[fire]
ignition = 0.3
burn_rate = 3.0
heat = 1.0
smoke = 0.5
[smoke]
buoyancy = 1.0
resolution_scale = 2
[output]
frames = 4
steps_per_frame = 2
)";

TEST_F(RunCommand, AFireWritesFuelAndFlameGridsAndResumesOnBothBackends) {
    const fs::path s = scene("torch.toml", kTorch);
    const std::vector<Vec3> centres = smokeCentres();
    std::map<std::string, std::vector<VdbSample>> cpuGrids;
    for (const std::string device : {"--device cpu", "--device vulkan"}) {
        const fs::path whole = mDir / ("whole" + device.substr(9)),
                       parts = mDir / ("parts" + device.substr(9));
        const RunResult r = simulate(s, whole, device);
        ASSERT_EQ(r.status, 0) << device << ": " << r.err;
        const VdbFrameInfo info = readVdbFrameInfo(whole / "torch_0004.vdb");
        for (const char* grid : {"density", "temperature", "fuel", "flame"}) {
            ASSERT_NE(info.grid(grid), nullptr) << grid;
            EXPECT_EQ(info.grid(grid)->gridClass, "fog volume") << grid;
        }
        // Fuel burns where it is hot: a flame in the torch, and no cell holds more fuel than
        // four frames of the source's rate with nothing burnt.
        const auto fuel = sampleVdbGrid(whole / "torch_0004.vdb", "fuel", centres);
        const auto flame = sampleVdbGrid(whole / "torch_0004.vdb", "flame", centres);
        double mostFlame = 0.0, mostFuel = 0.0;
        for (std::size_t c = 0; c < centres.size(); ++c) {
            // A scalar grid's sample is its value in x.
            mostFlame = std::max(mostFlame, flame[c].value[0]);
            mostFuel = std::max(mostFuel, fuel[c].value[0]);
            EXPECT_GE(fuel[c].value[0], 0.0) << device << " " << c;
            EXPECT_GE(flame[c].value[0], 0.0) << device << " " << c;
        }
        EXPECT_GT(mostFlame, 0.1) << device;
        EXPECT_GT(mostFuel, 0.0) << device;
        EXPECT_LT(mostFuel, 6.0 * 8 * 0.02) << device;

        // The device burns as the CPU reference does, to float32's precision.
        for (const char* grid : {"fuel", "flame", "temperature", "density"}) {
            const auto values = sampleVdbGrid(whole / "torch_0004.vdb", grid, centres);
            if (device == "--device cpu") {
                cpuGrids[grid] = values;
                continue;
            }
            double most = 0.0, difference = 0.0;
            for (std::size_t c = 0; c < centres.size(); ++c) {
                most = std::max(most, std::abs(cpuGrids[grid][c].value[0]));
                difference =
                    std::max(difference, std::abs(values[c].value[0] - cpuGrids[grid][c].value[0]));
            }
            EXPECT_LE(difference, 1e-4 * most) << grid;
        }

        // Stopped after frame 2 and resumed: the same fuel and flame, value for value.
        ASSERT_EQ(simulate(s, parts, device + " --frames 2").status, 0) << device;
        ASSERT_EQ(simulate(s, parts, device + " --resume").status, 0) << device;
        EXPECT_EQ(testing::slurp(parts / "torch.resume"), testing::slurp(whole / "torch.resume"))
            << device;
        for (const char* grid : {"fuel", "flame", "temperature"}) {
            const auto a = sampleVdbGrid(whole / "torch_0004.vdb", grid, centres);
            const auto b = sampleVdbGrid(parts / "torch_0004.vdb", grid, centres);
            for (std::size_t c = 0; c < centres.size(); ++c)
                ASSERT_EQ(a[c].value, b[c].value) << device << " " << grid << " cell " << c;
        }
    }
}

/// Peak resident memory of `command` in MiB (GNU time's %M), its status asserted 0.
long peakMiB(const std::string& command, const fs::path& report) {
    const int raw = std::system(("/usr/bin/time -f %M -o " + report.string() + " " + command +
                                 " >/dev/null 2>&1 </dev/null")
                                    .c_str());
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << command;
    return std::stol(testing::slurp(report)) / 1024;
}

TEST_F(RunCommand, PreviewsOfEveryFrameKeepMemoryFlatAndTheSheetShowsAtMost48) {
    const fs::path s = scene("hot.toml", kHotDisk);
    ASSERT_EQ(run(precompute(s)).status, 0);
    const auto previewRun = [&](int frames, const fs::path& out) {
        return peakMiB("env -u MODEFLOW_CACHE_DIR " + testing::cliPath() + " run " + s.string() +
                           " --out " + out.string() + " --cache-dir " + mCache.string() +
                           " --preview-every 1 --frames " + std::to_string(frames),
                       mDir / "time.txt");
    };
    // From 48 previews on the sheet is full: 48 more frames hold nothing more (every preview
    // held until the sheet was 1.8 MiB a frame here: 86 MiB more).
    const long full = previewRun(48, mDir / "full"), many = previewRun(96, mDir / "many");
    // AddressSanitizer keeps freed memory in quarantine (up to 256 MiB): its peak follows what was
    // ever allocated, not what is held.
    if (!testing::kAddressSanitizer) {
        EXPECT_LT(many - full, 24) << full << " MiB for 48 frames, " << many << " for 96";
    }
    const auto frame = testing::readPng(mDir / "many" / "hot_0096.png");
    const auto sheet = testing::readPng(mDir / "many" / "hot_contact.png");
    ASSERT_TRUE(frame && sheet);
    const int thumbnail = int(std::lround(frame->height * 256.0 / frame->width));
    EXPECT_EQ(sheet->width, 6 * (256 + 4) + 4);
    EXPECT_EQ(sheet->height, 8 * (thumbnail + 4) + 4) << "48 of the 96 previews, 8 rows of 6";

    // A resumed run's sheet shows the frames before the resume too: they are read from the files.
    ASSERT_EQ(simulate(s, mDir / "parts", "--preview-every 1 --frames 3").status, 0);
    ASSERT_EQ(simulate(s, mDir / "parts", "--preview-every 1 --resume").status, 0);
    const auto resumed = testing::readPng(mDir / "parts" / "hot_contact.png");
    ASSERT_TRUE(resumed);
    EXPECT_EQ(resumed->width, 4 * (256 + 4) + 4) << "the 4 frames of the whole run";
}

TEST_F(RunCommand, CpuReferenceRunGivesTheSameSmoke) {
    for (const std::string integrator : {"", "linearized"}) {
        const fs::path s = scene("hot.toml", hotDisk(integrator));
        const fs::path gpuOut = mDir / ("gpu" + integrator), cpuOut = mDir / ("cpu" + integrator);
        ASSERT_EQ(simulate(s, gpuOut, "--frames 2").status, 0);
        const RunResult cpu = simulate(s, cpuOut, "--frames 2 --device cpu");
        ASSERT_EQ(cpu.status, 0) << cpu.err;
        const std::vector<Vec3> centres = smokeCentres();
        const auto a = sampleVdbGrid(gpuOut / "hot_0002.vdb", "density", centres);
        const auto b = sampleVdbGrid(cpuOut / "hot_0002.vdb", "density", centres);
        for (std::size_t c = 0; c < centres.size(); ++c)
            EXPECT_NEAR(a[c].value[0], b[c].value[0], 1e-5) << integrator << " " << c;
    }
}

TEST_F(RunCommand, MhdRunsOnTheCpuReferenceWithAMagneticGridAndResumes) {
    const fs::path s = scene("rotor.toml", kMhdRotor);
    const RunResult whole = simulate(s, mDir / "whole", "--device cpu");
    ASSERT_EQ(whole.status, 0) << whole.err;
    ASSERT_EQ(simulate(s, mDir / "parts", "--device cpu --frames 2").status, 0);
    const RunResult resumed = simulate(s, mDir / "parts", "--device cpu --resume");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("resuming after frame 2"), std::string::npos) << resumed.err;

    const VdbFrameInfo info = readVdbFrameInfo(mDir / "whole" / "rotor_0004.vdb");
    ASSERT_NE(info.grid("magnetic"), nullptr);
    EXPECT_EQ(info.grid("magnetic")->valueType, "vec3s");
    EXPECT_GT(info.grid("magnetic")->activeVoxels, 100);
    const std::vector<Vec3> centres = smokeCentres();
    // The field points left to right at the centre of the disk.
    const Vec3 centre[] = {{0.0, 0.0, 0.0}};
    const Vec3 b = sampleVdbGrid(mDir / "whole" / "rotor_0001.vdb", "magnetic", centre)[0].value;
    EXPECT_GT(b[0], 10.0 * std::abs(b[1])) << b[0] << ", " << b[1];
    // The resumed run continues from the saved v and F: the same values, not close ones.
    for (const char* name : {"rotor_0003.vdb", "rotor_0004.vdb"})
        for (const char* grid : {"density", "vel", "magnetic"}) {
            const auto a = sampleVdbGrid(mDir / "whole" / name, grid, centres);
            const auto c = sampleVdbGrid(mDir / "parts" / name, grid, centres);
            for (std::size_t i = 0; i < centres.size(); ++i)
                ASSERT_EQ(a[i].value, c[i].value) << name << " " << grid << " cell " << i;
        }
}

TEST_F(RunCommand, MhdRunsOnAVulkanDeviceLikeOnTheCpuReference) {
    const fs::path s = scene("rotor.toml", kMhdRotor);
    const RunResult gpu = simulate(s, mDir / "gpu", "--frames 2");
    ASSERT_EQ(gpu.status, 0) << gpu.err;
    ASSERT_EQ(simulate(s, mDir / "cpu", "--frames 2 --device cpu").status, 0);
    const std::vector<Vec3> centres = smokeCentres();
    for (const char* grid : {"density", "vel", "magnetic"}) {
        const auto a = sampleVdbGrid(mDir / "gpu" / "rotor_0002.vdb", grid, centres);
        const auto b = sampleVdbGrid(mDir / "cpu" / "rotor_0002.vdb", grid, centres);
        for (std::size_t c = 0; c < centres.size(); ++c)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(a[c].value[k], b[c].value[k], 1e-4) << grid << " cell " << c;
    }
}

TEST_F(RunCommand, BadInputIsRefusedBeforeAnyWork) {
    const fs::path s = scene("hot.toml", kHotDisk);
    EXPECT_NE(simulate(s, mDir / "f", "--frames 0").status, 0);
    std::ofstream(mDir / "file") << "x";
    expectRejected("run " + s.string() + " --out " + (mDir / "file" / "sub").string() +
                       " --cache-dir " + mCache.string(),
                   "output folder");
    expectRejected(
        "run " + scene("dt.toml", std::string(kHotDisk) + "[simulation]\ndt = -1\n").string() +
            " --cache-dir " + mCache.string(),
        "dt");
    const std::string cone = testing::sceneFixture("cone_source_2d");
    expectRejected("run " + scene("cone.toml", cone).string() + " --cache-dir " + mCache.string(),
                   "[[source]]");
    expectRejected("run " + s.string() + " --out " + (mDir / "g").string() +
                       " --device gpu0 --cache-dir " + mCache.string(),
                   "--device gpu0");
    EXPECT_FALSE(fs::exists(mDir / "g"))
        << "the output folder was made before the device was checked";
}

TEST_F(RunCommand, WhatTheBackendCannotDoIsRefusedBeforeThePrecompute) {
    const fs::path s = scene("hot.toml", kHotDisk);
    // A device index that is not there: the device is opened before any precompute.
    expectRejected("run " + s.string() + " --out " + (mDir / "f").string() +
                       " --device 7 --cache-dir " + mCache.string(),
                   "device");
    EXPECT_FALSE(fs::exists(mCache)) << "the precompute ran before the device was opened";
    const fs::path windy = scene("windy.toml", R"([grid]
resolution = [16, 8]
bounds_min = [0.0, 0.0]
bounds_max = [2.0, 1.0]
[basis]
velocity_modes = 12
[wind]
velocity = [1.0, 0.0]
)");
    // A wind runs on both.
    for (const char* device : {"cpu", "vulkan"}) {
        const fs::path out = mDir / (std::string("w_") + device);
        const RunResult r =
            run("run " + windy.string() + " --device " + device + " --frames 2 --out " +
                out.string() + " --cache-dir " + mCache.string());
        EXPECT_EQ(r.status, 0) << device << ": " << r.err;
        EXPECT_TRUE(fs::exists(out / "windy_0002.vdb")) << device;
    }
}

TEST_F(RunCommand, HeldModesRunOnBothBackendsAndWakeStillFluid) {
    // From rest, with two modes held at amplitude: they set the rest moving, alike on both.
    std::string text =
        std::string(testing::kSmallDisk) +
        "[simulation]\ndt = 0.02\n[initial]\nvelocity = \"modes\"\namplitudes = [[1, 0.5], [2, "
        "0.5]]\n"
        "[forcing]\nhold_modes = \"1-2\"\n[output]\nframes = 2\nsteps_per_frame = 5\n";
    const fs::path forced = scene("forced.toml", text);
    std::vector<double> energies;
    for (const char* device : {"cpu", "vulkan"}) {
        const RunResult still = run("modes " + forced.string() + " --csv --device " + device +
                                    " --cache-dir " + mCache.string());
        ASSERT_EQ(still.status, 0) << device << ": " << still.err;
        const fs::path out = mDir / (std::string("f_") + device);
        const RunResult r = run("run " + forced.string() + " --device " + device + " --out " +
                                out.string() + " --cache-dir " + mCache.string());
        EXPECT_EQ(r.status, 0) << device << ": " << r.err;
        EXPECT_TRUE(fs::exists(out / "forced_0002.vdb")) << device;
        // Energy grows from the held modes' 0.25 as the others pick up motion.
        const std::string last = still.out.substr(still.out.rfind('\n', still.out.size() - 2) + 1);
        energies.push_back(std::stod(last.substr(last.find(',', last.find(',') + 1) + 1)));
        EXPECT_GT(energies.back(), 0.25) << device << "\n" << still.out;
    }
    EXPECT_NEAR(energies[1], energies[0], 1e-5 * energies[0]);
}

TEST_F(RunCommand, ASourceOutsideTheDomainIsRefusedNamingIt) {
    const fs::path s = scene("outside.toml", std::string(testing::kSmallDisk) + R"(
[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.2
[[source]]
shape = "ball"
center = [1.05, 1.05]
radius = 0.05
)");
    const RunResult r = simulate(s, mDir / "f", "--frames 1");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("[[source]] #2 covers no fluid cell"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(mDir / "f" / "outside_0001.vdb"));
}

/// A closed octahedron, scaled by `scale`: a mesh domain small enough for quick tests.
std::string octahedron(double scale) {
    std::string obj;
    const double v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& p : v)
        obj += "v " + std::to_string(scale * p[0]) + " " + std::to_string(scale * p[1]) + " " +
               std::to_string(scale * p[2]) + "\n";
    obj += "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    return obj;
}

TEST_F(RunCommand, ResumeAfterEditingOnlyTheMeshIsRefused) {
    std::ofstream(mDir / "shape.obj") << octahedron(1.0);
    const fs::path s = scene("mesh.toml", testing::sceneFixture("mesh_run_3d"));
    ASSERT_EQ(simulate(s, mDir / "out", "--frames 1 --device cpu").status, 0);
    std::ofstream(mDir / "shape.obj") << octahedron(0.9);  // the scene's text is unchanged
    const RunResult resumed = simulate(s, mDir / "out", "--resume --device cpu");
    EXPECT_NE(resumed.status, 0) << "a resume continued in another basis";
    EXPECT_NE(resumed.err.find("basis (mesh file)"), std::string::npos) << resumed.err;
}

TEST_F(RunCommand, AShorterRerunLeavesNoFramesOfTheEarlierRun) {
    const fs::path s = scene("hot.toml", kHotDisk), out = mDir / "frames";
    ASSERT_EQ(simulate(s, out).status, 0);
    std::ofstream(out / "other_0003.vdb") << "another scene's frame";
    std::ofstream(out / "hot_notes.txt") << "the user's";
    std::ofstream(out / "hot_particles_notes.ply") << "the user's too";
    const RunResult rerun = simulate(s, out, "--frames 2");
    ASSERT_EQ(rerun.status, 0) << rerun.err;
    EXPECT_NE(rerun.err.find("files of an earlier hot run"), std::string::npos) << rerun.err;
    EXPECT_TRUE(fs::exists(out / "hot_0002.vdb"));
    EXPECT_FALSE(fs::exists(out / "hot_0003.vdb")) << "a frame of the earlier, longer run is left";
    EXPECT_FALSE(fs::exists(out / "hot_0004.vdb")) << "a frame of the earlier, longer run is left";
    EXPECT_TRUE(fs::exists(out / "hot_particles_0002.ply"));
    EXPECT_FALSE(fs::exists(out / "hot_particles_0003.ply")) << "its particles are left";
    EXPECT_TRUE(fs::exists(out / "hot_particles_notes.ply"));
    EXPECT_TRUE(fs::exists(out / "other_0003.vdb"));
    EXPECT_TRUE(fs::exists(out / "hot_notes.txt"));
}

TEST_F(RunCommand, ASecondRunIntoTheSameFolderIsRefused) {
    const fs::path s = scene("hot.toml", kHotDisk), out = mDir / "frames";
    fs::create_directories(out);
    // This process holds the folder as a running `modeflow run` would.
    const int held = ::open(RunFolder::lockPath(out, "hot").c_str(), O_RDWR | O_CREAT, 0644);
    ASSERT_GE(held, 0);
    ASSERT_EQ(::flock(held, LOCK_EX), 0);
    const RunResult second = simulate(s, out);
    EXPECT_NE(second.status, 0);
    EXPECT_NE(second.err.find("another modeflow run"), std::string::npos) << second.err;
    EXPECT_FALSE(fs::exists(out / "hot_0001.vdb"));
    ::close(held);  // the first run ends: the folder is free again
    const RunResult after = simulate(s, out, "--frames 1");
    EXPECT_EQ(after.status, 0) << after.err;
}

TEST_F(RunCommand, RunsKilledAtRandomPointsResumeToTheUninterruptedFrames) {
    // Checkpoints every 3 frames: a run killed anywhere resumes after the last multiple of 3 it
    // checkpointed and writes the frames after it again, the same to the bit; killed twice
    // (after a random frame file shows, then again) and resumed to the end, the folder holds what
    // an uninterrupted run writes.
    const fs::path s = scene("hot.toml", kHotDisk);
    const fs::path whole = mDir / "whole", parts = mDir / "parts";
    ASSERT_EQ(simulate(s, whole, "--frames 12 --checkpoint-every 3").status, 0);
    std::mt19937 random(29);
    std::string args = "--frames 12 --checkpoint-every 3";
    for (int kill = 0; kill < 2; ++kill) {
        const int seen = 2 + int(random() % 5) + 4 * kill;  // frame 2…6, then 6…10
        const std::string command = "exec " + testing::cliPath() + " run " + s.string() +
                                    " --out " + parts.string() + " --cache-dir " + mCache.string() +
                                    " " + args + " >/dev/null 2>&1";
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        const fs::path shows = parts / frameFileName("hot", seen);
        int status = 0;
        while (!fs::exists(shows) && ::waitpid(child, &status, WNOHANG) == 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ::kill(child, SIGKILL);
        ::waitpid(child, &status, 0);
        args += " --resume";
        if (fs::exists(parts / "hot.resume")) {
            const int frame = readCheckpoint(parts / "hot.resume").frame;
            std::cout << "killed once frame " << seen << " showed: checkpoint of frame " << frame
                      << "\n";
            EXPECT_TRUE(frame % 3 == 0 || frame == 12) << "checkpoint of frame " << frame;
        } else {
            std::cout << "killed once frame " << seen << " showed: no checkpoint yet\n";
        }
    }
    const RunResult resumed = simulate(s, parts, args);
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_EQ(testing::slurp(parts / "hot.resume"), testing::slurp(whole / "hot.resume"));
    const std::vector<Vec3> centres = smokeCentres();
    for (int frame = 1; frame <= 12; ++frame) {
        const std::string file = frameFileName("hot", frame);
        for (const char* grid : {"density", "vel"}) {
            const auto a = sampleVdbGrid(whole / file, grid, centres);
            const auto b = sampleVdbGrid(parts / file, grid, centres);
            for (std::size_t cell = 0; cell < centres.size(); ++cell)
                ASSERT_EQ(a[cell].value, b[cell].value) << file << " " << grid << " " << cell;
        }
    }
    // A count that is not one is refused before any work.
    const RunResult zero = simulate(s, mDir / "zero", "--checkpoint-every 0");
    EXPECT_NE(zero.status, 0);
    EXPECT_NE(zero.err.find("--checkpoint-every"), std::string::npos) << zero.err;
    EXPECT_FALSE(fs::exists(mDir / "zero" / "hot_0001.vdb"));
}

TEST_F(RunCommand, PartialFilesOfKilledRunsAreRemoved) {
    const fs::path s = scene("hot.toml", kHotDisk), out = mDir / "frames";
    fs::create_directories(out);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);  // a process that is gone, as a killed run's is
    const fs::path partial = out / ("hot_0002.vdb.tmp-" + std::to_string(child));
    std::ofstream(partial) << "half a frame";
    const RunResult r = simulate(s, out, "--frames 1");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(fs::exists(partial));
    EXPECT_NE(r.err.find("partial files of killed runs"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace modeflow
