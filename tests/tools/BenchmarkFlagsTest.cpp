/// @file BenchmarkFlagsTest.cpp
/// The benchmark harnesses' command lines (tools/bench): a mistyped flag stops them with its name
/// and a non-zero status instead of running nothing and reporting success, and `--device N`
/// picks the Vulkan device of the runtime benchmarks; every table runs its smallest case to the
/// end (a table that stops with an error is caught here, not by the next person timing it).

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

TEST_F(BenchmarkFlags, EveryRuntimeTableRunsItsSmallestCase) {
    const std::pair<const char*, const char*> cases[] = {
        {"bench_contraction", "contraction/(dense/N:50|sparse/N:100)/"},
        {"bench_modal_steps", "modalStep/midpoint/N:50/"},
        {"bench_runtime_stages", "runtime_step/dim:2/cells:256/N:50/"},
        {"bench_basis_kernels", "projection_float32/dim:2/cells:256/N:50/"},
        {"bench_smoke_advection", "smokeStep/maccormack/dim:2/cells:128/"},
        {"bench_preview", "volumePreview"},
        {"bench_closed_form", "deviceStep/torus_2d/"},
        {"bench_tensor_free", "vulkan_tensor_free/N:250/"},
    };
    for (const auto& [bench, filter] : cases) {
        const RunResult r = runProgram(kBenchFolder + "/" + bench,
                                       std::string("--benchmark_filter='") + filter + "'");
        EXPECT_EQ(r.status, 0) << bench << ": " << r.err;
        EXPECT_NE(r.out.find("/iterations:"), std::string::npos)
            << bench << " timed nothing: " << r.out << r.err;
    }
}

}  // namespace
}  // namespace modeflow::testing
