/// @file HarmonicDomainsTest.cpp
/// Domains with a hole hold a harmonic velocity mode (κ = 0, seed §6.3.1). Its κ² is stored as
/// exactly 0, and `modes` and `run` simulate such domains on both devices; the solve's round-off
/// (±1e-11) used to stop them with "kappa^2 values must be non-negative".

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

/// An ellipse minus a disk at 72², 40 modes: the solve gives the harmonic mode κ² = −2.7e-11.
const char* kEllipseMinusDisk = R"(
[grid]
resolution = [72, 72]
bounds_min = [-1.1, -1.1]
bounds_max = [1.1, 1.1]
[[domain]]
shape = "ellipsoid"
center = [0.0, 0.0]
radii = [1.0, 0.7]
[[domain]]
shape = "ball"
center = [0.2, 0.0]
radius = 0.25
op = "subtract"
[basis]
velocity_modes = 40
scalar_modes = 8
[simulation]
dt = 0.02
viscosity = 0.001
[initial]
velocity = "random"
energy = 1.0
[[source]]
shape = "ball"
center = [-0.6, 0.0]
radius = 0.15
density = 1.0
[output]
frames = 2
steps_per_frame = 2
)";

class HarmonicDomains : public Cli {
protected:
    /// `modes` and `run` on both devices, then the cache's harmonic count and first κ².
    void expectSimulated(const fs::path& scene) const {
        const std::string cache = " --cache-dir " + mCache.string();
        for (const std::string device : {"cpu", "vulkan"}) {
            const RunResult modes =
                run("modes " + scene.string() + " --steps 5 --device " + device + cache);
            EXPECT_EQ(modes.status, 0) << device << ": " << modes.err;
            const RunResult frames =
                run("run " + scene.string() + " --frames 2 --device " + device + " --out " +
                    (mDir / ("frames_" + device)).string() + cache);
            EXPECT_EQ(frames.status, 0) << device << ": " << frames.err;
        }
        std::vector<fs::path> bases;  // the mask file of a finer smoke grid lies beside it
        for (const auto& e : fs::directory_iterator(mCache))
            if (e.path().extension() == ".mfbasis") bases.push_back(e.path());
        ASSERT_EQ(bases.size(), 1u);
        const RunResult inspect = run("inspect --json " + bases.front().string());
        ASSERT_EQ(inspect.status, 0) << inspect.err;
        const auto velocity = nlohmann::json::parse(inspect.out)["velocity"];
        EXPECT_EQ(velocity["harmonic"], 1);
        EXPECT_EQ(velocity["eigenvalues"][0].get<double>(), 0.0)
            << "the harmonic kappa^2 is not exactly 0";
        EXPECT_GT(velocity["eigenvalues"][1].get<double>(), 1.0);
    }
};

TEST_F(HarmonicDomains, TheAnnulusSceneRunsWithItsHarmonicModeAtKappaZero) {
    expectSimulated(fs::path(MODEFLOW_SOURCE_DIR) / "scenes" / "annulus_2d.toml");
}

TEST_F(HarmonicDomains, AnEllipseMinusADiskRunsWithItsHarmonicModeAtKappaZero) {
    expectSimulated(scene("ellipse_minus_disk.toml", kEllipseMinusDisk));
}

}  // namespace
}  // namespace modeflow
