// `modeflow precompute` stopped in the middle of its sliced eigensolves (precompute/README.md,
// "Sliced eigensolves and MPI") resumes from the intervals it finished: the log says so, the basis
// is the one an uninterrupted run computes, damaged checkpoints are solved again, and none is left
// once the cache is written. The interruption: MODEFLOW_TEST_STOP_AFTER_INTERVALS, a test hook
// that makes the solver fail once it has solved and kept that many intervals.

#include <gtest/gtest.h>

#include "engine/format/CacheFile.h"
#include "tests/support/BasisComparison.h"
#include "tests/support/CliFixture.h"
#include "tests/support/SceneFixtures.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

/// Sliced solves of one interval (the Neumann scalar), two (Dirichlet scalars: their count falls
/// short of Weyl's leading term) and two (velocity).
const std::string kDisk = testing::sceneFixture("sliced_disk_2d");

std::vector<fs::path> checkpoints(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(folder))
        if (e.path().extension() == ".mfslice") files.push_back(e.path());
    return files;
}

class PrecomputeResume : public Cli {
protected:
    /// The basis of an uninterrupted run.
    BasisCache uninterrupted() {
        const RunResult r =
            run("precompute " + mScene.string() + " --cache-dir " + (mDir / "whole").string());
        EXPECT_EQ(r.status, 0) << r.err;
        return readCache(r.out.substr(0, r.out.find('\n')));
    }
    /// A precompute into the test's cache that stops after `intervals` solved intervals.
    RunResult interrupted(int intervals) {
        return runProgram("MODEFLOW_TEST_STOP_AFTER_INTERVALS=" + std::to_string(intervals) + " " +
                              testing::cliPath(),
                          precompute(mScene));
    }

    void expectSameBasis(const BasisCache& a, const BasisCache& b) {
        EXPECT_LE(testing::eigenvalueDifference(b.velocity.eigenvalues, a.velocity.eigenvalues),
                  1e-12)
            << "velocity eigenvalues";
        EXPECT_LE(testing::spanDifference(a.velocity.eigenvalues, a.velocity.modes,
                                          b.velocity.modes, a.faceStar),
                  1e-9)
            << "velocity spans";
        EXPECT_LE(testing::eigenvalueDifference(b.scalar.eigenvalues, a.scalar.eigenvalues), 1e-12)
            << "scalar eigenvalues";
        EXPECT_LE(testing::spanDifference(a.scalar.eigenvalues, a.scalar.modes, b.scalar.modes,
                                          a.scalar.cellStar),
                  1e-9)
            << "scalar spans";
    }

    const fs::path mScene = scene("disk.toml", kDisk);
};

TEST_F(PrecomputeResume, InterruptedPrecomputeResumesFromItsFinishedIntervals) {
    // Stopped in the velocity solve's second interval: both scalar solves (1 + 2 intervals) and
    // the velocity solve's first interval are kept.
    const RunResult stopped = interrupted(4);
    ASSERT_NE(stopped.status, 0);
    EXPECT_NE(stopped.err.find("velocity eigensolve: stopped after 4 intervals"), std::string::npos)
        << stopped.err;
    EXPECT_EQ(checkpoints(mCache).size(), 4u);
    EXPECT_EQ(cacheFiles(), 4) << "no cache written";

    const RunResult resumed = run(precompute(mScene));
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    for (const char* line :
         {"scalar (Neumann) eigensolve: 1 of 1 intervals from an interrupted run",
          "scalar (Dirichlet) eigensolve: 2 of 2 intervals from an interrupted run",
          "velocity eigensolve: 1 of 2 intervals from an interrupted run"})
        EXPECT_NE(resumed.err.find(line), std::string::npos) << resumed.err;
    EXPECT_TRUE(checkpoints(mCache).empty()) << "checkpoints left after the cache was written";
    expectSameBasis(uninterrupted(), readCache(resumed.out.substr(0, resumed.out.find('\n'))));
}

TEST_F(PrecomputeResume, DamagedCheckpointsAreSolvedAgain) {
    ASSERT_NE(interrupted(4).status, 0);
    for (const fs::path& file : checkpoints(mCache)) fs::resize_file(file, fs::file_size(file) / 2);

    const RunResult resumed = run(precompute(mScene));
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("is truncated or corrupt"), std::string::npos) << resumed.err;
    EXPECT_NE(resumed.err.find("; solving it again"), std::string::npos) << resumed.err;
    EXPECT_EQ(resumed.err.find("from an interrupted run"), std::string::npos) << resumed.err;
    EXPECT_TRUE(checkpoints(mCache).empty());
    expectSameBasis(uninterrupted(), readCache(resumed.out.substr(0, resumed.out.find('\n'))));
}

TEST_F(PrecomputeResume, ForcedPrecomputeSolvesEveryIntervalAgain) {
    ASSERT_NE(interrupted(4).status, 0);
    const RunResult forced = run(precompute(mScene, "--force"));
    ASSERT_EQ(forced.status, 0) << forced.err;
    EXPECT_EQ(forced.err.find("from an interrupted run"), std::string::npos) << forced.err;
    EXPECT_TRUE(checkpoints(mCache).empty());
}

}  // namespace
}  // namespace modeflow
