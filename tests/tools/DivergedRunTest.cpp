/// @file DivergedRunTest.cpp
/// A run whose integrator is unstable at its step size stops with a message naming the step, the
/// integrator and [simulation].dt, on both devices (the CPU reference used to crash with a
/// segmentation fault when NaN positions reached the smoke sampling).

#include <string>

#include <gtest/gtest.h>

#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;

/// The explicit rule at dt = 50 on the small disk: the state overflows within a few steps.
const std::string kUnstable = std::string(testing::kSmallDisk) + R"(
[simulation]
dt = 50.0
integrator = "explicit"
[initial]
velocity = "random"
energy = 1.0
seed = 3
[[source]]
shape = "ball"
center = [0.0, -0.5]
radius = 0.25
density = 1.0
temperature = 1.0
[smoke]
buoyancy = 1.0
[output]
frames = 20
steps_per_frame = 2
)";

TEST_F(Cli, AnUnstableRunStopsWithTheDivergenceMessageOnBothDevices) {
    const std::string s = scene("unstable.toml", kUnstable).string();
    for (const std::string device : {"cpu", "vulkan"}) {
        const RunResult r = run("run " + s + " --device " + device + " --out " +
                                (mDir / device).string() + " --cache-dir " + mCache.string());
        EXPECT_EQ(r.status, 1) << device << ": " << r.err;
        EXPECT_NE(r.err.find("modeflow: error: the modal state diverged at step "),
                  std::string::npos)
            << device << ": " << r.err;
        EXPECT_NE(
            r.err.find(
                "; explicit is unstable at this step size: lower [simulation].dt or use midpoint"),
            std::string::npos)
            << device << ": " << r.err;
    }
    const RunResult modes = run("modes " + s + " --cache-dir " + mCache.string());
    EXPECT_EQ(modes.status, 1) << modes.err;
    EXPECT_NE(
        modes.err.find("; explicit is unstable at this step size: lower --dt or use midpoint"),
        std::string::npos)
        << modes.err;
}

}  // namespace
}  // namespace modeflow
