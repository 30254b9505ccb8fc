/// @file InitialStateTest.cpp
/// An [initial] state that no step can take (infinite, or too large to square in double
/// precision) is refused where it is built, naming the [initial] key that made it, instead of
/// being blamed on dt by the integrator later.

#include <string>

#include <gtest/gtest.h>

#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;

class InitialState : public Cli {
protected:
    /// `modes` and `run --device cpu` both refuse the scene, naming `key` and not dt.
    void expectRefused(const std::string& initial, const std::string& key,
                       const std::string& simulation = "") const {
        const std::string s =
            scene("initial.toml", std::string(testing::kSmallDisk) + simulation + initial).string();
        for (const std::string& command :
             {"modes " + s,
              "run " + s + " --device cpu --frames 1 --out " + (mDir / "frames").string()}) {
            const RunResult r = run(command + " --cache-dir " + mCache.string());
            EXPECT_EQ(r.status, 1) << command << ": " << r.err;
            EXPECT_NE(r.err.find(key), std::string::npos) << command << ": " << r.err;
            EXPECT_EQ(r.err.find("dt"), std::string::npos) << command << ": " << r.err;
        }
    }
};

TEST_F(InitialState, ARandomEnergyWhoseSquareOverflowsIsRefused) {
    expectRefused("[initial]\nvelocity = \"random\"\nenergy = 1e300\n", "[initial].energy");
}

TEST_F(InitialState, HugeModalAmplitudesAreRefused) {
    expectRefused("[initial]\nvelocity = \"modes\"\namplitudes = [[2, 1e200]]\n",
                  "[initial].amplitudes");
}

TEST_F(InitialState, AVortexOfHugeStrengthIsRefused) {
    expectRefused(R"([initial]
velocity = "vortices"
[[initial.vortex]]
center = [0.2, 0.0]
strength = 1e300
radius = 0.3
)",
                  "[[initial.vortex]] #1.strength");
}

TEST_F(InitialState, AHugeMagneticEnergyIsRefused) {
    expectRefused("[initial]\nvelocity = \"random\"\nmagnetic_energy = 1e300\n",
                  "[initial].magnetic_energy", "[simulation]\nmhd = true\n");
}

}  // namespace
}  // namespace modeflow
