// `mpirun -n 2 modeflow precompute` (precompute/README.md, "Sliced eigensolves and MPI"): the ranks
// share the sliced eigensolves, rank 0 alone writes the cache, and the basis is the one a single
// process computes.

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

/// An off-centre ball with a hole through it: no exact symmetry, so every eigenspace is
/// one-dimensional or nearly so.
const std::string kHollowBall = testing::sceneFixture("hollow_ball_3d");

class MpiPrecompute : public Cli {
protected:
    /// `mpirun MPIRUN_ARGS -n 2 modeflow precompute` of the hollow ball into the folder "two".
    RunResult runTwoRanks(const std::string& mpirunArgs) const {
        return runProgram(MODEFLOW_MPIRUN, "--allow-run-as-root --oversubscribe " + mpirunArgs +
                                               " -n 2 " + testing::cliPath() + " precompute " +
                                               mScene.string() + " --cache-dir " +
                                               (mDir / "two").string());
    }
    /// runTwoRanks(mpirunArgs): its log says `line`, rank 0 alone prints the cache path, and the
    /// basis is the one a single process computes.
    void expectSingleProcessBasis(const std::string& mpirunArgs, const std::string& line) const;

    const fs::path mScene = scene("hollow.toml", kHollowBall);
};

void MpiPrecompute::expectSingleProcessBasis(const std::string& mpirunArgs,
                                             const std::string& line) const {
    const RunResult alone =
        run("precompute " + mScene.string() + " --cache-dir " + (mDir / "alone").string());
    ASSERT_EQ(alone.status, 0) << alone.err;
    const RunResult two = runTwoRanks(mpirunArgs);
    ASSERT_EQ(two.status, 0) << two.err;
    EXPECT_NE(two.err.find(line), std::string::npos) << two.err;
    EXPECT_EQ(std::count(two.out.begin(), two.out.end(), '\n'), 1)
        << "only rank 0 prints the cache path: " << two.out;

    const BasisCache a = readCache(alone.out.substr(0, alone.out.find('\n')));
    const BasisCache b = readCache(two.out.substr(0, two.out.find('\n')));
    EXPECT_EQ(b.velocity.harmonic, 1);
    EXPECT_EQ(b.velocity.harmonic, a.velocity.harmonic);
    EXPECT_LE(testing::eigenvalueDifference(b.velocity.eigenvalues, a.velocity.eigenvalues), 1e-9)
        << "velocity eigenvalues";
    EXPECT_LE(testing::spanDifference(a.velocity.eigenvalues, a.velocity.modes, b.velocity.modes,
                                      a.faceStar),
              1e-7)
        << "velocity spans";
    EXPECT_LE(testing::eigenvalueDifference(b.scalar.eigenvalues, a.scalar.eigenvalues), 1e-9)
        << "scalar eigenvalues";
    EXPECT_LE(testing::spanDifference(a.scalar.eigenvalues, a.scalar.modes, b.scalar.modes,
                                      a.scalar.cellStar),
              1e-7)
        << "scalar spans";
    EXPECT_EQ(b.coefficients.packed.size(), a.coefficients.packed.size());
}

TEST_F(MpiPrecompute, TwoRanksComputeTheSingleProcessBasis) {
    // One partition per rank: each rank solves its own subintervals.
    expectSingleProcessBasis("", "precompute on 2 MPI ranks\n");
}

TEST_F(MpiPrecompute, OneFactorizationOverTwoRanksComputesTheSingleProcessBasis) {
    // One partition: every factorization (MUMPS) spans both ranks.
    expectSingleProcessBasis("-x PETSC_OPTIONS='-eps_krylovschur_partitions 1'",
                             "precompute on 2 MPI ranks in 1 partition (each factorization on 2 "
                             "ranks)");
}

TEST_F(MpiPrecompute, InterruptedPrecomputeResumesOnEveryRank) {
    // Stopped (a test hook) once the first interval, the Neumann scalar solve's only one, is kept.
    const RunResult stopped = runTwoRanks("-x MODEFLOW_TEST_STOP_AFTER_INTERVALS=1");
    ASSERT_NE(stopped.status, 0);
    EXPECT_NE(stopped.err.find("stopped after 1 intervals"), std::string::npos) << stopped.err;
    // Every rank reads rank 0's checkpoint, or the ranks would disagree and hang or differ.
    expectSingleProcessBasis("",
                             "scalar (Neumann) eigensolve: 1 of 1 intervals from an "
                             "interrupted run");
    for (const auto& e : fs::directory_iterator(mDir / "two"))
        EXPECT_NE(e.path().extension(), ".mfslice") << "left after the cache was written";
}

/// How often `needle` stands in `text`.
int occurrences(const std::string& text, const std::string& needle) {
    int n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + 1))
        ++n;
    return n;
}

TEST_F(MpiPrecompute, OneRankSpeaksForARefusalEveryRankMeets) {
    const fs::path bad = scene("bad.toml", std::string(kHollowBall) + "[simulation]\ndt = -1\n");
    const RunResult r = runProgram(
        MODEFLOW_MPIRUN, "--allow-run-as-root --oversubscribe -n 2 " + testing::cliPath() +
                             " precompute " + bad.string() + " --cache-dir " + mCache.string());
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(occurrences(r.err, "modeflow: error: "), 1) << r.err;
    EXPECT_NE(r.err.find("dt"), std::string::npos) << r.err;
}

TEST_F(MpiPrecompute, CommandsOtherThanPrecomputeAreRefusedUnderSeveralRanks) {
    // Two ranks of `run` raced for the output folder's lock and wrote nothing: refused, once.
    for (const std::string& command :
         {"run " + mScene.string() + " --out " + (mDir / "frames").string(),
          "modes " + mScene.string(), "inspect " + mScene.string()}) {
        const RunResult r = runProgram(
            MODEFLOW_MPIRUN, "--allow-run-as-root --oversubscribe -n 2 " + testing::cliPath() +
                                 " " + command + " --cache-dir " + mCache.string());
        EXPECT_NE(r.status, 0) << command;
        EXPECT_EQ(occurrences(r.err, "modeflow: error: "), 1) << command << ": " << r.err;
        EXPECT_NE(r.err.find("only `modeflow precompute` shares its work among MPI ranks: start "
                             "it without mpirun (2 ranks here)"),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(cacheFiles(), 0) << "work started: " << command;
    }
    EXPECT_FALSE(fs::exists(mDir / "frames"));
}

}  // namespace
}  // namespace modeflow
