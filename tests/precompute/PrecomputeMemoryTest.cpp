/// @file PrecomputeMemoryTest.cpp
/// The precompute's memory estimate (precompute/PrecomputeMemory.h): its DOF counts and the
/// refusal it makes before any work.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "engine/core/Error.h"
#include "precompute/Precompute.h"
#include "precompute/PrecomputeMemory.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// Sets MODEFLOW_MEMORY_LIMIT for one scope.
class MemoryLimit {
public:
    explicit MemoryLimit(double bytes) {
        setenv("MODEFLOW_MEMORY_LIMIT", std::to_string(std::uint64_t(bytes)).c_str(), 1);
    }
    ~MemoryLimit() { unsetenv("MODEFLOW_MEMORY_LIMIT"); }
};

std::string refusal(const SceneSpec& scene) {
    try {
        requirePrecomputeMemory(scene);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(PrecomputeMemory, TheDofCountsAreThoseOfTheDomainWithinAFewPercent) {
    for (const SceneSpec& scene :
         {testing::unitBallScene(2, 96, 4, 0), testing::unitBallScene(3, 20, 4, 0)}) {
        const PrecomputeMemory estimate = estimatePrecomputeMemory(scene);
        Progress quiet = Progress::silent();
        const BasisCache cache = computeBasis(scene, quiet);
        const double faces = double(cache.faces.size()), cells = double(cache.cells.size());
        EXPECT_NEAR(estimate.velocityDofs / faces, 1.0, 0.12)
            << scene.grid.dim << "D: " << estimate.velocityDofs << " estimated, " << faces
            << " faces";
        EXPECT_NEAR(estimate.scalarDofs / cells, 1.0, 0.12)
            << scene.grid.dim << "D: " << estimate.scalarDofs << " estimated, " << cells
            << " cells";
    }
}

TEST(PrecomputeMemory, ARefusalNamesTheResolutionAndTheModesWhenFewerWouldFit) {
    // 400 modes with a dense tensor: the packed coefficients dominate.
    SceneSpec scene = testing::unitBallScene(2, 64, 400, 0);
    scene.basis.coefficients = CoefficientStorage::Dense;
    const PrecomputeMemory estimate = estimatePrecomputeMemory(scene);
    ASSERT_LT(2.0 * estimate.gridBytes, estimate.peakBytes);
    {
        const MemoryLimit limit(0.5 * (estimate.gridBytes + estimate.peakBytes));
        const std::string message = refusal(scene);
        EXPECT_EQ(
            message.rfind(
                "[grid].resolution = [64, 64] with velocity modes up to 400: the precompute (", 0),
            0u)
            << message;
        EXPECT_NE(message.find("(estimate), but only "), std::string::npos) << message;
        EXPECT_NE(message.find(
                      "are available (MODEFLOW_MEMORY_LIMIT); lower the mode counts in [basis] or "
                      "[grid].resolution"),
                  std::string::npos)
            << message;
    }
    {
        const MemoryLimit limit(0.5 * estimate.gridBytes);
        const std::string message = refusal(scene);
        EXPECT_EQ(message.rfind("[grid].resolution = [64, 64]: the precompute (", 0), 0u)
            << message;
        EXPECT_NE(message.find("; lower [grid].resolution"), std::string::npos) << message;
    }
    {
        const MemoryLimit limit(std::ceil(estimate.peakBytes));
        EXPECT_EQ(refusal(scene), "");
    }
}

}  // namespace
}  // namespace modeflow
