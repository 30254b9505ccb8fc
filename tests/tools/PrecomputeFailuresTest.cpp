/// @file PrecomputeFailuresTest.cpp
/// The precompute fails with one message of ours naming the stage: nothing printed by the
/// libraries below it (CHOLMOD), and no "internal error".

#include <string>

#include <gtest/gtest.h>

#include "tests/support/CliFixture.h"
#include "tests/support/SceneFixtures.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;

TEST_F(Cli, ExtremelyScaledScenesFailWithOurMessageOnly) {
    // Spacings of 6e148 make the shifted Laplacian numerically indefinite, and CHOLMOD used to
    // print "CHOLMOD warning: matrix not positive definite" on stdout before our message; at
    // 6e-152 the scaled operator overflows and Spectra's exception ended as "internal error".
    for (const std::string scale : {"1e150", "1e-150"}) {
        const std::string text = testing::replaced(
            testing::kSmallDisk, {{"[24, 24]", "[48, 48]"},
                                  {"[-1.1, -1.1]", "[-" + scale + ", -" + scale + "]"},
                                  {"[1.1, 1.1]", "[" + scale + ", " + scale + "]"},
                                  {"radius = 1.0", "radius = " + scale}});
        const RunResult r = run(precompute(scene("scaled.toml", text)));
        EXPECT_EQ(r.status, 1) << scale << ": " << r.err;
        EXPECT_EQ((r.out + r.err).find("CHOLMOD"), std::string::npos)
            << scale << ": " << r.out << r.err;
        EXPECT_NE(r.err.find("modeflow: error: "), std::string::npos) << scale << ": " << r.err;
        EXPECT_EQ(r.err.find("internal error"), std::string::npos) << scale << ": " << r.err;
    }
}

}  // namespace
}  // namespace modeflow
