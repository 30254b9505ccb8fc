/// @file BenchmarkFlagsTest.cpp
/// The benchmark harnesses' command lines (tools/bench): a mistyped flag stops them with its name
/// and a non-zero status instead of running nothing and reporting success, and `--device N`
/// picks the Vulkan device of the runtime benchmarks.

#include <string>

#include <gtest/gtest.h>

#include "tests/support/CliFixture.h"

namespace modeflow::testing {
namespace {

using BenchmarkFlags = Cli;

const std::string kBenchFolder = MODEFLOW_BENCH_DIR;

TEST_F(BenchmarkFlags, UnknownFlagsAreRefusedWithTheirName) {
    for (const char* bench : {"bench_dynamics", "bench_contraction"}) {
        const RunResult r = runProgram(kBenchFolder + "/" + bench, "--only typo");
        EXPECT_EQ(r.status, 1) << bench;
        EXPECT_NE(r.err.find("unrecognized command-line flag: --only"), std::string::npos)
            << bench << ": " << r.err;
        EXPECT_EQ(r.out.find("Benchmark"), std::string::npos) << bench << " ran: " << r.out;
    }
}

TEST_F(BenchmarkFlags, DeviceFlagPicksTheVulkanDevice) {
    const std::string bench = kBenchFolder + "/bench_contraction";
    const RunResult listed = runProgram(bench, "--device 0 --benchmark_list_tests");
    EXPECT_EQ(listed.status, 0) << listed.err;
    EXPECT_NE(listed.out.find("contraction/dense/N:200"), std::string::npos) << listed.out;
    EXPECT_NE(listed.err.find("chosen   #0"), std::string::npos) << listed.err;

    const RunResult missing = runProgram(bench, "--device 99 --benchmark_list_tests");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("no suitable Vulkan device"), std::string::npos) << missing.err;
    EXPECT_TRUE(missing.out.empty()) << missing.out;

    const RunResult noValue = runProgram(bench, "--device");
    EXPECT_EQ(noValue.status, 1);
    EXPECT_NE(noValue.err.find("--device needs a value"), std::string::npos) << noValue.err;
}

}  // namespace
}  // namespace modeflow::testing
