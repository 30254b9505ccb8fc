/// @file HarmonicDomainsTest.cpp
/// Domains with a hole hold a harmonic velocity mode (κ = 0, seed §6.3.1). Its κ² is stored as
/// exactly 0, and `modes` and `run` simulate such domains on both devices; the solve's round-off
/// (±1e-11) used to stop them with "kappa^2 values must be non-negative".

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/CliFixture.h"
#include "tests/support/SceneFixtures.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;

/// tests/data/scenes/ellipse_minus_disk_2d.toml: the solve gives the harmonic mode κ² = −2.7e-11.
const std::string kEllipseMinusDisk = testing::sceneFixture("ellipse_minus_disk_2d");

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
