/// @file OutOfMemoryStageTest.cpp
/// A failed allocation inside a precompute stage ends as "out of memory in <stage>", not as an
/// escaped std::bad_alloc ("internal error"). The allocation fails for real: the stage runs in a
/// child process whose address space is capped. Alone in its executable because a child forked
/// after OpenMP has started its threads deadlocks in the next parallel region.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "engine/core/Error.h"
#include "precompute/Precompute.h"
#include "tests/support/Sanitizers.h"
#include "tests/support/TestScenes.h"

extern "C" void omp_set_num_threads(int);  // libgomp, linked through the precompute

namespace modeflow {
namespace {

/// Bytes of address space this process holds now (VmSize).
std::size_t addressSpace() {
    std::ifstream status("/proc/self/status");
    std::string key;
    std::size_t kib = 0;
    while (status >> key) {
        if (key == "VmSize:" && status >> kib) return kib * 1024;
        status.ignore(1 << 12, '\n');
    }
    return 0;
}

/// What `work` reports in a child process whose address space may grow by `headroom` bytes only:
/// the message of a modeflow::Error, "other: <what>" for another exception, "" for none.
std::string inCappedChild(std::size_t headroom, const std::function<void()>& work) {
    int channel[2];
    if (pipe(channel) != 0) return "pipe failed";
    const pid_t child = fork();
    if (child == 0) {
        close(channel[0]);
        omp_set_num_threads(1);  // no thread stacks to fit under the cap
        const rlim_t cap = addressSpace() + headroom;
        const rlimit limit{cap, cap};
        setrlimit(RLIMIT_AS, &limit);
        std::string report;
        try {
            work();
        } catch (const Error& e) {
            report = e.what();
        } catch (const std::exception& e) {
            report = std::string("other: ") + e.what();
        }
        const ssize_t written = write(channel[1], report.data(), report.size());
        _exit(written == ssize_t(report.size()) ? 0 : 1);  // no destructors: the cap stays harmless
    }
    close(channel[1]);
    std::string report;
    char buffer[512];
    for (ssize_t n; (n = read(channel[0], buffer, sizeof buffer)) > 0;)
        report.append(buffer, std::size_t(n));
    close(channel[0]);
    int status = 0;
    waitpid(child, &status, 0);
    return report;
}

TEST(OutOfMemoryStage, AFailedAllocationEndsAsOutOfMemoryInItsStage) {
    if (testing::kAddressSanitizer)
        GTEST_SKIP() << "AddressSanitizer aborts on a failed allocation instead of throwing";
    // 512² cells need about 70 MiB of cut-cell measures; the child may take 24 MiB more. The
    // memory limit lets the estimate pass, so that the stage itself runs out.
    SceneSpec scene = testing::unitBallScene(2, 512, 4, 0);
    setenv("MODEFLOW_MEMORY_LIMIT", "1000000000000000", 1);
    const std::string report = inCappedChild(std::size_t(24) << 20, [&] {
        Progress quiet = Progress::silent();
        computeBasis(scene, quiet);
    });
    unsetenv("MODEFLOW_MEMORY_LIMIT");
    EXPECT_EQ(
        report.rfind("out of memory in domain and cut-cell measures (the estimated peak was ", 0),
        0u)
        << report;
    EXPECT_NE(report.find("; lower [grid].resolution or the mode counts in [basis]"),
              std::string::npos)
        << report;
}

}  // namespace
}  // namespace modeflow
