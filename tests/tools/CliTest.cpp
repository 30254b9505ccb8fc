// The `modeflow` command line, run as users run it: exit codes, messages that name what is
// wrong, and no cache file left behind by a failure (tools/README.md, "Command line").

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "tests/support/CliFixture.h"
#include "tests/support/SceneFixtures.h"

namespace {

using modeflow::testing::Cli;
using modeflow::testing::RunResult;
using modeflow::testing::slurp;
namespace fs = std::filesystem;

using modeflow::testing::kSmallDisk;
using modeflow::testing::replaced;
using modeflow::testing::sceneFixture;

/// The table `modes --csv` prints: its header line and each row's numbers.
struct Csv {
    std::string header;
    std::vector<std::vector<double>> rows;
};

Csv parseCsv(const std::string& out) {
    std::istringstream lines(out);
    Csv csv;
    std::getline(lines, csv.header);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream fields(line);
        std::vector<double>& row = csv.rows.emplace_back();
        for (std::string f; std::getline(fields, f, ',');) row.push_back(std::stod(f));
    }
    return csv;
}

/// The energy column (the third) of `modes --csv`.
std::vector<double> csvEnergies(const std::string& out) {
    std::vector<double> energies;
    for (const auto& row : parseCsv(out).rows) energies.push_back(row.at(2));
    return energies;
}

TEST_F(Cli, PrecomputePrintsTheCachePathLastAndReusesIt) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    const RunResult first = run(precompute(s));
    ASSERT_EQ(first.status, 0) << first.err;
    std::istringstream lines(first.out);
    std::string line, last;
    while (std::getline(lines, line)) last = line;
    ASSERT_TRUE(fs::exists(last)) << "last stdout line: " << last;
    EXPECT_EQ(fs::path(last).parent_path(), mCache);
    const auto written = fs::last_write_time(last);

    const RunResult second = run(precompute(s));
    ASSERT_EQ(second.status, 0);
    EXPECT_NE(second.err.find("up to date"), std::string::npos) << second.err;
    EXPECT_EQ(fs::last_write_time(last), written);

    // Simulation settings do not shape the basis: same cache.
    const fs::path sameBasis =
        scene("disk2.toml", std::string(kSmallDisk) + "[simulation]\ndt = 0.5\n");
    EXPECT_NE(run(precompute(sameBasis)).err.find("up to date"), std::string::npos);
    // A change that matters gives another cache file.
    const fs::path other =
        scene("disk3.toml", replaced(kSmallDisk, "radius = 1.0", "radius = 0.9"));
    ASSERT_EQ(run(precompute(other)).status, 0);
    EXPECT_EQ(cacheFiles(), 2);

    const RunResult forced = run(precompute(s, "--force"));
    ASSERT_EQ(forced.status, 0);
    EXPECT_EQ(forced.err.find("up to date"), std::string::npos);
}

TEST_F(Cli, InspectJsonReportsTheContractKeys) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    const RunResult r =
        run("inspect " + s.string() + " --cache-dir " + mCache.string() + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["dim"], 2);
    EXPECT_EQ(j["resolution"], nlohmann::json({24, 24}));
    EXPECT_EQ(j["periodic"], nlohmann::json({false, false}));
    EXPECT_EQ(j["open"], nlohmann::json::array());
    EXPECT_EQ(j["velocity"]["count"], 8);
    EXPECT_EQ(j["velocity"]["eigenvalues"].size(), 8u);
    EXPECT_EQ(j["velocity"]["harmonic"], 0);
    EXPECT_LE(j["velocity"]["max_divergence"].get<double>(), 1e-10);
    EXPECT_LE(j["velocity"]["orthonormality_error"].get<double>(), 1e-10);
    EXPECT_EQ(j["scalar"]["count"], 4);
    EXPECT_EQ(j["scalar"]["boundary"], "neumann");
    EXPECT_EQ(j["velocity"]["source"], "eigensolve");
    EXPECT_EQ(j["scalar"]["source"], "eigensolve");
    EXPECT_EQ(j["velocity"]["checked_modes"], 8);
    EXPECT_TRUE(j["timings"].contains("velocity_eigensolve"));
    EXPECT_EQ(j["coefficients"]["storage"], "dense");
    EXPECT_EQ(j["coefficients"]["antisymmetry_error"], 0.0);
    EXPECT_EQ(j["coefficients"]["stored"], 8 * 8 * 7 / 2);
    const auto& ev = j["velocity"]["eigenvalues"];
    for (size_t i = 1; i < ev.size(); ++i) EXPECT_LE(ev[i - 1].get<double>(), ev[i].get<double>());
    // The cache path works as the argument too.
    const RunResult direct = run("inspect " + j["cache"]["path"].get<std::string>() + " --json");
    ASSERT_EQ(direct.status, 0) << direct.err;
    EXPECT_EQ(nlohmann::json::parse(direct.out)["velocity"]["eigenvalues"], ev);
}

TEST_F(Cli, TensorFreeScenesStoreNoTensorAndRunLikeDenseOnes) {
    const std::string initial = "[initial]\nvelocity = \"random\"\nenergy = 2.0\n";
    const fs::path free =
        scene("free.toml", replaced(kSmallDisk, "scalar_modes = 4",
                                    "scalar_modes = 4\ncoefficients = \"tensor-free\"") +
                               initial);
    const fs::path dense = scene(
        "dense.toml",
        replaced(kSmallDisk, "scalar_modes = 4", "scalar_modes = 4\ncoefficients = \"dense\"") +
            initial);
    const std::string freeCache = " --cache-dir " + (mDir / "free").string();
    const RunResult inspect = run("inspect " + free.string() + freeCache + " --json");
    ASSERT_EQ(inspect.status, 0) << inspect.err;
    const auto j = nlohmann::json::parse(inspect.out);
    EXPECT_EQ(j["coefficients"]["storage"], "none");
    EXPECT_EQ(j["coefficients"]["stored"], 0);
    EXPECT_GT(j["coefficients"]["quadrature_elements"].get<int>(), 0);

    const std::string steps = " --steps 50 --dt 0.05 --integrator midpoint --csv";
    const RunResult a = run("modes " + free.string() + freeCache + steps);
    const RunResult b = run("modes " + dense.string() + " --cache-dir " + mCache.string() + steps);
    ASSERT_EQ(a.status, 0) << a.err;
    ASSERT_EQ(b.status, 0) << b.err;
    const Csv got = parseCsv(a.out), want = parseCsv(b.out);
    ASSERT_EQ(got.rows.size(), want.rows.size());
    // The state's figures, not the solver's: without a cheap Jacobian the tensor-free midpoint
    // rule iterates fixed points where the dense one runs Newton (iterations, residual).
    const std::size_t stateColumns = 5;  // step, time, energy, enstrophy, cross_helicity
    ASSERT_EQ(want.header.rfind("step,time,energy,enstrophy,cross_helicity,", 0), 0u)
        << want.header;
    double worst = 0.0;
    for (std::size_t r = 0; r < got.rows.size(); ++r)
        for (std::size_t c = 0; c < stateColumns; ++c)
            worst = std::max(worst, std::abs(got.rows[r][c] - want.rows[r][c]) /
                                        std::max(1.0, std::abs(want.rows[r][c])));
    EXPECT_LT(worst, 1e-10) << "largest difference in the modes table's state columns";

    const RunResult device = run("modes " + free.string() + freeCache + steps + " --device vulkan");
    ASSERT_EQ(device.status, 0) << device.err;
    const std::vector<double> expected = csvEnergies(a.out), energies = csvEnergies(device.out);
    ASSERT_EQ(energies.size(), expected.size());
    for (std::size_t step = 0; step < energies.size(); ++step)
        EXPECT_NEAR(energies[step] / expected[step], 1.0, 1e-5)
            << "step " << step << " on the device";
}

TEST_F(Cli, TensorFreeIsRefusedForClosedFormAndSurfaceBases) {
    // A whole box with free-slip walls has closed-form bases: no columns, no vorticity quadrature.
    const std::string box =
        replaced(sceneFixture("unit_box_3d"), {{"[10, 8, 6]", "[4, 3, 3]"},
                                               {"velocity_modes = 30", "velocity_modes = 6"},
                                               {"scalar_modes = 5", "scalar_modes = 1"}});
    const fs::path free = scene("box_free.toml", box + "coefficients = \"tensor-free\"\n");
    const std::string closedForm = "a whole box with free-slip walls gets closed-form bases";
    expectRejected("precompute " + free.string() + " --cache-dir " + mCache.string(), closedForm);
    // Its cache made by auto (sparse coefficients), then the scene asks for tensor-free: refused
    // when the run loads the cache, on either backend.
    const fs::path automatic = scene("box_auto.toml", box);
    const RunResult made =
        run("precompute " + automatic.string() + " --cache-dir " + mCache.string());
    ASSERT_EQ(made.status, 0) << made.err;
    for (const char* device : {"cpu", "vulkan"}) {
        const RunResult r = run("modes " + free.string() + " --steps 2 --csv --device " + device +
                                " --cache-dir " + mCache.string());
        EXPECT_NE(r.status, 0) << device;
        EXPECT_NE(
            r.err.find(
                "modeflow: error: [basis].coefficients = \"tensor-free\": a closed-form basis"),
            std::string::npos)
            << device << ": " << r.err;
    }

    // A surface's coefficients are always assembled: refused when the scene is read.
    std::ofstream(mDir / "tetrahedron.obj") << "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n"
                                               "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
    const fs::path surface =
        scene("surface_free.toml",
              "[surface]\nmesh = \"tetrahedron.obj\"\n[basis]\nvelocity_modes = 2\n"
              "scalar_modes = 1\ncoefficients = \"tensor-free\"\n");
    fs::remove_all(mCache);
    expectRejected("precompute " + surface.string() + " --cache-dir " + mCache.string(),
                   "[basis].coefficients");
    expectRejected("modes " + surface.string() + " --cache-dir " + mCache.string(),
                   "always assembled (tensor-free advection runs on grid bases only)");
}

TEST_F(Cli, InspectSaysWhichAxesArePeriodic) {
    // A channel periodic along x: one harmonic field, the uniform flow along it.
    const fs::path s = scene("channel.toml", sceneFixture("periodic_channel_2d"));
    const RunResult json =
        run("inspect " + s.string() + " --cache-dir " + mCache.string() + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    const auto j = nlohmann::json::parse(json.out);
    EXPECT_EQ(j["periodic"], nlohmann::json({true, false}));
    EXPECT_EQ(j["velocity"]["harmonic"], 1);
    EXPECT_EQ(j["dofs"]["faces"], 16 * 8 + 16 * 7)
        << "every x-face (16 a row, the seam's once), y-faces off the walls";
    const RunResult text = run("inspect " + s.string() + " --cache-dir " + mCache.string());
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("grid       2D [16,8], periodic x, "), std::string::npos) << text.out;
}

TEST_F(Cli, InspectNamesTheOpenSidesOfAnEigensolvedBox) {
    const fs::path s =
        scene("open.toml",
              "[grid]\nresolution = [8, 6]\nbounds_min = [0, 0]\nbounds_max = [1, 0.75]\n"
              "open = [\"y_max\", \"x_min\"]\n[basis]\nvelocity_modes = 6\n"
              "scalar_modes = 0\n");
    const RunResult json =
        run("inspect " + s.string() + " --cache-dir " + mCache.string() + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    const auto j = nlohmann::json::parse(json.out);
    EXPECT_EQ(j["open"], nlohmann::json({"x_min", "y_max"}));
    EXPECT_EQ(j["velocity"]["source"], "eigensolve");
    const RunResult text = run("inspect " + s.string() + " --cache-dir " + mCache.string());
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("grid       2D [8,6], open x_min, y_max, "), std::string::npos)
        << text.out;
}

TEST_F(Cli, ConservativeSmokeRunsOnEitherBackend) {
    const fs::path s = scene("kept.toml", kSmallDisk +
                                              "[[source]]\nshape = \"ball\"\ncenter = [0, -0.4]\n"
                                              "radius = 0.2\n[smoke]\nbuoyancy = 1.0\n"
                                              "advection = \"conservative\"\n");
    for (const char* device : {"vulkan", "cpu"}) {
        const RunResult r = run("run " + s.string() + " --device " + device + " --frames 2 --out " +
                                (mDir / device).string() + " --cache-dir " + mCache.string());
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(fs::exists(mDir / device / "kept_0002.vdb"));
    }
}

TEST_F(Cli, InspectNamesTheClosedFormBasesOfAWholeBox) {
    // No [[domain]] and free-slip walls: both bases in closed form, sparse coefficients.
    const fs::path s = scene("box.toml", sceneFixture("unit_box_3d"));
    RunResult r = run("inspect " + s.string() + " --cache-dir " + mCache.string() + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["velocity"]["source"], "closed-form");
    EXPECT_EQ(j["scalar"]["source"], "closed-form");
    EXPECT_EQ(j["velocity"]["count"], 30);
    EXPECT_EQ(j["velocity"]["checked_modes"], 30);
    EXPECT_LE(j["velocity"]["max_divergence"].get<double>(), 1e-12);
    EXPECT_LE(j["velocity"]["orthonormality_error"].get<double>(), 1e-12);
    EXPECT_LE(j["scalar"]["orthonormality_error"].get<double>(), 1e-12);
    EXPECT_EQ(j["coefficients"]["storage"], "sparse");
    EXPECT_TRUE(j["timings"].contains("closed_form_velocity"));
    r = run("inspect " + j["cache"]["path"].get<std::string>());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("harmonic), closed-form"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("neumann modes, closed-form"), std::string::npos) << r.out;
    // No-slip walls keep the eigensolver.
    const fs::path noSlip = scene("noslip.toml", slurp(s) + "wall = \"no-slip\"\n");
    r = run("inspect " + noSlip.string() + " --cache-dir " + mCache.string() + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["velocity"]["source"], "eigensolve");
}

TEST_F(Cli, HelpDescribesEverySubcommand) {
    for (const char* sub : {"precompute", "inspect"}) {
        const RunResult r = run(std::string(sub) + " --help");
        EXPECT_EQ(r.status, 0);
        EXPECT_NE(r.out.find("--cache-dir"), std::string::npos) << sub;
    }
    EXPECT_NE(run("").status, 0);
}

TEST_F(Cli, BadScenesAreRejectedWithTheKeyNamed) {
    expectRejected(precompute(scene("a.toml", replaced(kSmallDisk, "scalar_modes", "scalar_mode"))),
                   "scalar_mode");
    expectRejected(
        precompute(scene("b.toml", replaced(kSmallDisk, "radius = 1.0", "radius = \"big\""))),
        "radius");
    expectRejected(precompute(scene("c.toml", replaced(kSmallDisk, "[24, 24]", "[1, 24]"))),
                   "resolution");
    expectRejected(
        precompute(scene("d.toml", replaced(kSmallDisk, "[24, 24]", "[4000, 4000, 4000]"))),
        "resolution");
    expectRejected(precompute(scene("e.toml", replaced(kSmallDisk, "bounds_max = [1.1, 1.1]",
                                                       "bounds_max = [-2.0, 1.1]"))),
                   "bounds");
    expectRejected(precompute(mDir / "missing.toml"), "missing.toml");
}

TEST_F(Cli, EmptyOrMissingDomainsAreRejected) {
    // A ball far outside the grid box.
    expectRejected(precompute(scene("miss.toml", replaced(kSmallDisk, "center = [0.0, 0.0]",
                                                          "center = [5.0, 5.0]"))),
                   "[[domain]]");
    // Two disjoint balls intersected: nothing left.
    const std::string empty =
        std::string(kSmallDisk) +
        "[[domain]]\nshape = \"ball\"\ncenter = [0.0, 0.0]\nradius = 0.05\nop = \"subtract\"\n"
        "[[domain]]\nshape = \"ball\"\ncenter = [0.0, 0.0]\nradius = 0.04\nop = \"intersect\"\n";
    expectRejected(precompute(scene("empty.toml", empty)), "[[domain]]");
}

TEST_F(Cli, TooManyModesAreRejected) {
    const std::string tiny = replaced(kSmallDisk, "[24, 24]", "[6, 6]");
    expectRejected(
        precompute(scene("v.toml", replaced(tiny, "velocity_modes = 8", "velocity_modes = 100"))),
        "[basis]");
    expectRejected(
        precompute(scene("s.toml", replaced(tiny, "scalar_modes = 4", "scalar_modes = 100"))),
        "scalar_modes");
}

TEST_F(Cli, BadMeshesAreRejected) {
    const std::string meshScene = sceneFixture("mesh_domain_3d");
    expectRejected(precompute(scene("m1.toml", replaced(meshScene, "MESH", "nowhere.obj"))),
                   "nowhere.obj");
    std::ofstream(mDir / "garbage.obj") << "this is not\x01 an obj file\nf 7 8 9\n";
    expectRejected(precompute(scene("m2.toml", replaced(meshScene, "MESH", "garbage.obj"))),
                   "garbage.obj");
    // A cube missing its top face.
    std::ofstream(mDir / "open.obj") << "v -.5 -.5 -.5\nv .5 -.5 -.5\nv .5 .5 -.5\nv -.5 .5 -.5\n"
                                        "v -.5 -.5 .5\nv .5 -.5 .5\nv .5 .5 .5\nv -.5 .5 .5\n"
                                        "f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    expectRejected(precompute(scene("m3.toml", replaced(meshScene, "MESH", "open.obj"))),
                   "open.obj");
}

TEST_F(Cli, UnwritableCacheDirectoryIsRejectedBeforeAnyWork) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    std::ofstream(mDir / "plainfile") << "x";
    const RunResult r =
        run("precompute " + s.string() + " --cache-dir " + (mDir / "plainfile" / "sub").string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("cache directory"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("eigensolve"), std::string::npos) << "work started: " << r.err;
}

TEST_F(Cli, DamagedCachesAreRefusedAndRebuilt) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    const RunResult first = run(precompute(s));
    ASSERT_EQ(first.status, 0) << first.err;
    const fs::path cache = first.out.substr(0, first.out.find('\n'));
    const std::string good = slurp(cache);

    // Truncated.
    std::ofstream(cache, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() / 2);
    RunResult r = run("inspect " + cache.string() + " --json");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
    r = run(precompute(s));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("rebuilding"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(cache).size(), good.size());

    // One flipped byte in the payload.
    std::string corrupt = good;
    corrupt[corrupt.size() / 2] ^= 0x5a;
    std::ofstream(cache, std::ios::binary | std::ios::trunc) << corrupt;
    r = run("inspect " + cache.string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("corrupt"), std::string::npos) << r.err;

    // Not a cache at all.
    std::ofstream(mDir / "x.mfbasis") << "hello";
    r = run("inspect " + (mDir / "x.mfbasis").string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("not a modeflow basis cache"), std::string::npos) << r.err;
}

TEST_F(Cli, InspectTellsCachesFromScenesByTheirContents) {
    const auto inspect = [&](const fs::path& file) {
        return run("inspect " + file.string() + " --cache-dir " + mCache.string() + " --json");
    };
    const RunResult upper = inspect(scene("disk.TOML", kSmallDisk));
    ASSERT_EQ(upper.status, 0) << upper.err;
    const auto expected = nlohmann::json::parse(upper.out);
    const RunResult text = inspect(scene("disk.txt", kSmallDisk));
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_EQ(nlohmann::json::parse(text.out)["velocity"]["eigenvalues"],
              expected["velocity"]["eigenvalues"]);

    const fs::path renamed = mDir / "renamed.toml";
    fs::copy_file(expected["cache"]["path"].get<std::string>(), renamed);
    const RunResult cache = inspect(renamed);
    ASSERT_EQ(cache.status, 0) << cache.err;
    EXPECT_EQ(nlohmann::json::parse(cache.out)["velocity"]["eigenvalues"],
              expected["velocity"]["eigenvalues"]);

    std::ofstream(mDir / "picture.toml", std::ios::binary)
        << std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    const RunResult neither = inspect(mDir / "picture.toml");
    EXPECT_EQ(neither.status, 1);
    EXPECT_NE(neither.err.find("picture.toml is neither a modeflow basis cache"), std::string::npos)
        << neither.err;
}

TEST_F(Cli, AFolderThatCannotBeEnteredIsNamedNotCalledMissing) {
    // A folder others may not enter, owned by root: the commands run as nobody when the test runs
    // as root (root enters every folder), else the folder is made unenterable for this user.
    fs::permissions(mDir, fs::perms(0755));
    const fs::path locked = mDir / "locked";
    fs::create_directories(locked);
    const fs::path s = locked / "disk.toml", reachable = scene("disk.toml", kSmallDisk);
    std::ofstream(s) << kSmallDisk;
    const bool root = ::geteuid() == 0;
    fs::permissions(locked, fs::perms(root ? 0700 : 0));
    const std::string as = (root ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "") +
                           modeflow::testing::cliPath();
    const std::string denied =
        "cannot be reached: permission denied to enter the folder " + locked.string();
    for (const std::string& command :
         {"inspect " + s.string(), "precompute " + s.string() + " --cache-dir " + mCache.string(),
          "run " + s.string() + " --out " + (mDir / "out").string()}) {
        const RunResult r = runProgram(as, command);
        EXPECT_EQ(r.status, 1) << command << ": " << r.err;
        EXPECT_NE(r.err.find("modeflow: error: " + s.string() + ": " + denied), std::string::npos)
            << command << ": " << r.err;
        EXPECT_EQ(r.err.find("no such"), std::string::npos) << r.err;
    }
    // A cache folder behind it.
    const RunResult cache = runProgram(
        as, "precompute " + reachable.string() + " --cache-dir " + (locked / "cache").string());
    EXPECT_EQ(cache.status, 1) << cache.err;
    EXPECT_NE(cache.err.find(denied), std::string::npos) << cache.err;
}

TEST_F(Cli, OnlyASlicedPrecomputeLoadsMpiAndPetsc) {
    // The dynamic loader names every library it loads (LD_DEBUG=files): a command that slices
    // nothing starts without MPI, PETSc and SLEPc and the libraries they bring.
    const auto loaded = [&](const std::string& args) {
        return runProgram("env LD_DEBUG=files " + modeflow::testing::cliPath(), args);
    };
    const fs::path s = scene("disk.toml", kSmallDisk);
    for (const std::string& args :
         {std::string("--version"), "precompute " + s.string() + " --cache-dir " + mCache.string(),
          "inspect " + s.string() + " --cache-dir " + mCache.string()}) {
        const RunResult r = loaded(args);
        EXPECT_EQ(r.status, 0) << args;
        for (const char* library : {"libpetsc", "libslepc", "libmpi", "libmodeflow_petsc"})
            EXPECT_EQ(r.err.find(library), std::string::npos) << args << " loaded " << library;
    }
    // Above the size whose eigenproblems are solved densely (1200 unknowns).
    const fs::path sliced = scene(
        "sliced.toml",
        replaced(kSmallDisk, {{"[24, 24]", "[48, 48]"},
                              {"scalar_modes = 4", "scalar_modes = 4\neigensolver = \"slepc\""}}));
    const RunResult r =
        loaded("precompute " + sliced.string() + " --force --cache-dir " + mCache.string());
    EXPECT_EQ(r.status, 0) << r.err.substr(r.err.size() > 4000 ? r.err.size() - 4000 : 0);
    for (const char* library : {"libmodeflow_petsc", "libslepc", "libpetsc", "libmpi"})
        EXPECT_NE(r.err.find(library), std::string::npos)
            << "the sliced precompute loaded no " << library;
}

TEST_F(Cli, InspectRefusesFoldersAndDevicesByName) {
    fs::create_directories(mDir / "folder.mfbasis");
    for (const fs::path& target : {mDir / "folder.mfbasis", fs::path("/dev/zero")}) {
        const RunResult r = run("inspect " + target.string());
        EXPECT_EQ(r.status, 1) << "an internal error exits 2: " << r.err;
        EXPECT_NE(r.err.find("modeflow: error: " + target.string() + ": is a "), std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find(", not a cache or scene file"), std::string::npos) << r.err;
    }
    // A folder where the cache belongs is reported and replaced by a fresh cache... or refused
    // clearly when it cannot be.
    const fs::path s = scene("disk.toml", kSmallDisk);
    const RunResult first = run(precompute(s));
    ASSERT_EQ(first.status, 0) << first.err;
    const fs::path cache = first.out.substr(0, first.out.find('\n'));
    fs::remove(cache);
    fs::create_directories(cache / "inside");
    const RunResult again = run(precompute(s));
    EXPECT_EQ(again.status, 1) << again.err;
    EXPECT_NE(again.err.find(cache.string() + ": is a directory, not a cache file; rebuilding"),
              std::string::npos)
        << again.err;
    EXPECT_NE(again.err.find("modeflow: error: cannot write cache file " + cache.string() +
                             ": cannot rename"),
              std::string::npos)
        << again.err;
}

TEST_F(Cli, NumericOptionsRefuseNonsenseNamingTheOption) {
    const fs::path s = scene("disk.toml", kSmallDisk);
    const std::string cache = " --cache-dir " + mCache.string();
    const struct {
        std::string args, message;
    } cases[] = {
        {"stir " + s.string() + " --force nan",
         "--force: must be a finite number of at least 0, got \"nan\""},
        {"stir " + s.string() + " --force -1",
         "--force: must be a finite number of at least 0, got \"-1\""},
        {"stir " + s.string() + " --frames 0",
         "--frames: must be a whole number from 1 to 1000000, got \"0\""},
        {"stir " + s.string() + " --width 1e9",
         "--width: must be a whole number from 1 to 16384, got \"1e9\""},
        {"stir " + s.string() + " --height 0", "--height: must be a whole number from 1 to 16384"},
        {"modes " + s.string() + " --dt nan",
         "--dt: must be a finite number greater than 0, got \"nan\""},
        {"modes " + s.string() + " --dt inf",
         "--dt: must be a finite number greater than 0, got \"inf\""},
        {"modes " + s.string() + " --dt 0",
         "--dt: must be a finite number greater than 0, got \"0\""},
        {"modes " + s.string() + " --steps 2.5",
         "--steps: must be a whole number from 1 to 1000000000"},
        {"run " + s.string() + " --frames 0",
         "--frames: must be a whole number from 1 to 1000000, got \"0\""},
        {"run " + s.string() + " --frames 99999999999",
         "--frames: must be a whole number from 1 to 1000000"},
        {"run " + s.string() + " --preview-every -3",
         "--preview-every: must be a whole number from 1 to 1000000"},
    };
    for (const auto& c : cases) {
        const RunResult r = run(c.args + cache);
        EXPECT_NE(r.status, 0) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\nstderr: " << r.err;
        EXPECT_LT(r.err.size(), 300u) << c.args << "\nstderr: " << r.err;
        EXPECT_FALSE(fs::exists(mCache))
            << c.args << ": work started before the option was checked";
    }
}

TEST_F(Cli, ModesRunsTheReducedDynamicsAsCsv) {
    const fs::path s = scene(
        "modes.toml", std::string(kSmallDisk) + "[initial]\nvelocity = \"random\"\nenergy = 2.0\n");
    const RunResult r = run("modes " + s.string() + " --cache-dir " + mCache.string() +
                            " --steps 200 --dt 0.05 --integrator midpoint --csv");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(parseCsv(r.out).header.rfind("step,time,energy", 0), 0u) << r.out.substr(0, 80);
    const std::vector<double> energies = csvEnergies(r.out);
    ASSERT_EQ(energies.size(), 201u);
    double worst = 0.0;
    for (double e : energies) worst = std::max(worst, std::abs(e / energies[0] - 1.0));
    EXPECT_NEAR(energies[0], 2.0, 1e-12);
    EXPECT_LE(worst, 1e-12) << "midpoint must conserve energy";

    const RunResult bad = run("modes " + s.string() + " --cache-dir " + (mDir / "c2").string() +
                              " --integrator leapfrog");
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.err.find("leapfrog"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(mDir / "c2")) << "work started before the option was checked";
    const RunResult badDevice =
        run("modes " + s.string() + " --cache-dir " + mCache.string() + " --device gpu0");
    EXPECT_NE(badDevice.status, 0);
    EXPECT_NE(badDevice.err.find("--device gpu0"), std::string::npos) << badDevice.err;
}

TEST_F(Cli, ModesRunsOnTheVulkanDeviceLikeTheCpuReference) {
    const fs::path s = scene(
        "modes.toml", std::string(kSmallDisk) + "[initial]\nvelocity = \"random\"\nenergy = 2.0\n");
    for (const auto& [integrator, steps] : {std::pair<std::string, std::size_t>{"midpoint", 100},
                                            {"trapezoidal", 50},
                                            {"linearized", 100}}) {
        const std::string args = " --cache-dir " + mCache.string() + " --steps " +
                                 std::to_string(steps) + " --dt 0.02 --integrator " + integrator +
                                 " --csv";
        const RunResult cpu = run("modes " + s.string() + args);
        const RunResult gpu = run("modes " + s.string() + args + " --device vulkan");
        ASSERT_EQ(cpu.status, 0) << integrator << ": " << cpu.err;
        ASSERT_EQ(gpu.status, 0) << integrator << ": " << gpu.err;
        EXPECT_NE(gpu.err.find("Vulkan device:"), std::string::npos)
            << "the run must say which device runs";
        const std::vector<double> expected = csvEnergies(cpu.out), got = csvEnergies(gpu.out);
        ASSERT_EQ(got.size(), steps + 1) << integrator;
        ASSERT_EQ(got.size(), expected.size()) << integrator;
        const bool conserving = integrator != "trapezoidal";
        for (std::size_t step = 0; step < got.size(); ++step) {
            EXPECT_NEAR(got[step] / expected[step], 1.0, 1e-5) << integrator << ", step " << step;
            if (conserving) {
                EXPECT_NEAR(expected[step], expected[0], 1e-12 * expected[0])
                    << integrator << ", step " << step;
            }
        }
    }
}

TEST_F(Cli, ModesRefusesTheLinearizedRuleForMhdBeforeThePrecompute) {
    const fs::path mhd = scene("linear_mhd.toml", std::string(kSmallDisk) +
                                                      "[simulation]\nmhd = true\n"
                                                      "[initial]\nvelocity = \"random\"\n");
    for (const char* device : {"cpu", "vulkan"}) {
        const RunResult refused = run("modes " + mhd.string() + " --cache-dir " + mCache.string() +
                                      " --steps 5 --integrator linearized --device " + device);
        EXPECT_NE(refused.status, 0) << device;
        EXPECT_NE(refused.err.find("--integrator: the linearized rule is for fluids"),
                  std::string::npos)
            << device << ": " << refused.err;
        EXPECT_EQ(refused.err.find("eigensolve"), std::string::npos)
            << device << ": refused before the precompute";
    }
}

TEST_F(Cli, ModesStartsFromVorticesAndFromModalAmplitudes) {
    const std::string vortices = std::string(kSmallDisk) + R"(
[initial]
velocity = "vortices"
energy = 0.8
[[initial.vortex]]
center = [-0.2, 0.0]
strength = 1.0
radius = 0.2
[[initial.vortex]]
center = [0.2, 0.0]
strength = 1.0
radius = 0.2
)";
    const std::string args = " --cache-dir " + mCache.string() + " --steps 20 --dt 0.05 --csv";
    RunResult r = run("modes " + scene("vortices.toml", vortices).string() + args);
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<double> e = csvEnergies(r.out);
    ASSERT_EQ(e.size(), 21u) << r.out;
    EXPECT_NEAR(e.front(), 0.8, 1e-12) << "the projected state is rescaled to [initial].energy";
    EXPECT_NEAR(e.back() / e.front(), 1.0, 1e-10) << "midpoint conserves it";

    const std::string modes =
        std::string(kSmallDisk) +
        "[initial]\nvelocity = \"modes\"\namplitudes = [[1, 1.0], [3, -0.5]]\n";
    r = run("modes " + scene("modes.toml", modes).string() + args);
    ASSERT_EQ(r.status, 0) << r.err;
    e = csvEnergies(r.out);
    ASSERT_FALSE(e.empty());
    EXPECT_NEAR(e.front(), 0.5 * (1.0 + 0.25), 1e-12) << "energy = ½Σa²";

    const std::string band =
        std::string(kSmallDisk) + "[initial]\nvelocity = \"random\"\nenergy = 0.3\nband = [2, 5]\n";
    r = run("modes " + scene("band.toml", band).string() + args);
    ASSERT_EQ(r.status, 0) << r.err;
    e = csvEnergies(r.out);
    ASSERT_FALSE(e.empty());
    EXPECT_NEAR(e.front(), 0.3, 1e-12);

    r = run("modes " + scene("beyond.toml", replaced(modes, "[3, -0.5]", "[9, -0.5]")).string() +
            " --cache-dir " + (mDir / "c3").string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("[initial].amplitudes[1]: mode 9 is outside the basis"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(mDir / "c3")) << "the scene is checked before any precompute";
}

TEST_F(Cli, ModesRunsMhdConservingEnergyAndCrossHelicity) {
    expectRejected(precompute(scene(
                       "m1.toml", std::string(kSmallDisk) + "[initial]\nmagnetic_energy = 1.0\n")),
                   "mhd = true");
    expectRejected(precompute(scene("m2.toml", std::string(kSmallDisk) +
                                                   "[simulation]\nmhd = true\nalpha = 0.1\n")),
                   "alpha");
    const fs::path s = scene("mhd.toml", std::string(kSmallDisk) +
                                             "[simulation]\nmhd = true\n"
                                             "[initial]\nvelocity = \"random\"\nenergy = 1.0\n"
                                             "magnetic_energy = 0.5\n");
    const RunResult r = run("modes " + s.string() + " --cache-dir " + mCache.string() +
                            " --steps 100 --dt 0.05 --integrator midpoint --csv");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    EXPECT_EQ(csv.header, "step,time,energy,enstrophy,cross_helicity,iterations,residual");
    const auto& rows = csv.rows;
    ASSERT_EQ(rows.size(), 101u);
    EXPECT_NEAR(rows[0][2], 1.5, 1e-12) << "½|v|² + ½|F|²";
    for (const auto& row : rows) {
        EXPECT_NEAR(row[2], rows[0][2], 1e-12);
        EXPECT_NEAR(row[4], rows[0][4], 1e-12) << "cross helicity";
    }
    const RunResult device =
        run("modes " + s.string() + " --cache-dir " + mCache.string() +
            " --steps 100 --dt 0.05 --integrator midpoint --csv --device vulkan");
    ASSERT_EQ(device.status, 0) << device.err;
    const Csv onDevice = parseCsv(device.out);
    ASSERT_EQ(onDevice.rows.size(), rows.size());
    for (std::size_t step = 0; step < rows.size(); ++step) {
        EXPECT_NEAR(onDevice.rows[step][2], rows[step][2], 1e-5)
            << "energy on the device, step " << step;
        EXPECT_NEAR(onDevice.rows[step][4], rows[step][4], 1e-5)
            << "cross helicity on the device, step " << step;
    }
}

}  // namespace
