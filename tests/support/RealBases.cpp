#include "tests/support/RealBases.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "tests/support/TestScenes.h"

namespace modeflow::testing {

BasisCache sharedBasis(const SceneSpec& scene) {
    Progress quiet = Progress::silent();
    const char* folder = std::getenv("MODEFLOW_TEST_BASES");
    if (!folder || !*folder) return computeBasis(scene, quiet);
    return ensureCache(scene, folder, false, quiet).cache;
}

const BasisCache& disk2d() {
    static const BasisCache cache = sharedBasis(unitBallScene(2, 32, 20, 0));
    return cache;
}

const BasisCache& ball3d() {
    static const BasisCache cache = sharedBasis(unitBallScene(3, 12, 10, 0));
    return cache;
}

const BasisCache& disk2dHundredModes() {
    static const BasisCache cache = [] {
        SceneSpec scene = unitBallScene(2, 40, 100, 0);
        scene.basis.coefficients =
            CoefficientStorage::Dense;  // compared with, whatever auto chooses
        return sharedBasis(scene);
    }();
    return cache;
}

namespace {

SceneSpec withModes(SceneSpec scene, int velocityModes) {
    scene.basis.velocityModes = {{1, velocityModes}};
    scene.basis.scalarModes = 0;
    return scene;
}

}  // namespace

const BasisCache& periodicChannel2d() {
    static const BasisCache cache = sharedBasis(withModes(periodicChannelScene(32), 20));
    return cache;
}

const BasisCache& torusAroundDisk2d() {
    static const BasisCache cache =
        sharedBasis(withModes(periodicChannelScene(32, {true, true, false}), 20));
    return cache;
}

const BasisCache& torus3d() {
    SceneSpec scene = gridScene({8, 8, 8}, {-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}, 3);
    scene.grid.periodic = {true, true, true};
    static const BasisCache cache = sharedBasis(withModes(scene, 12));
    return cache;
}

void expectValidVelocityBasis(const BasisCache& cache) {
    const BasisChecks checks = checkBasis(cache);
    EXPECT_LE(checks.maxDivergence, 1e-10);
    EXPECT_LE(checks.velocityOrthonormality, 1e-10);
}

}  // namespace modeflow::testing
