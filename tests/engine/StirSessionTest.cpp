/// StirSession apart from any window, on the CPU reference: the status line names the integrator
/// as the scene file does, and the integrator key switches to midpoint and back.

#include <gtest/gtest.h>

#include <string>

#include "engine/core/SceneKeywords.h"
#include "engine/run/Backend.h"
#include "engine/stir/StirSession.h"
#include "precompute/Precompute.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {
namespace {

RunInputs smallRun(Integrator integrator) {
    SceneSpec scene;
    scene.name = "stir_session_test";
    scene.grid.dim = 2;
    scene.grid.resolution = {12, 12, 1};
    scene.grid.boundsMin = {0.0, 0.0, 0.0};
    scene.grid.boundsMax = {1.0, 1.0, 1.0};
    scene.basis.velocityModes = {{1, 6}};
    scene.basis.scalarModes = 0;
    scene.simulation.integrator = integrator;
    Progress quiet = Progress::silent();
    return prepareRun(scene, computeBasis(scene, quiet));
}

TEST(StirSession, StatusNamesTheIntegratorAsTheSceneFileDoes) {
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    for (const Integrator integrator :
         {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint}) {
        const RunInputs run = smallRun(integrator);
        stir::StirSession session(backend, run);
        const std::string status = session.status();
        EXPECT_EQ(status.rfind(std::string(sceneKeyword(integrator)) + " |", 0), 0u) << status;
    }
}

TEST(StirSession, TheIntegratorKeySwitchesToMidpointAndBack) {
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    const RunInputs run = smallRun(Integrator::Rk4);
    stir::StirSession session(backend, run);
    session.toggleIntegrator();
    EXPECT_EQ(session.settings().integrator, Integrator::Midpoint);
    session.toggleIntegrator();
    EXPECT_EQ(session.settings().integrator, Integrator::Explicit);
    EXPECT_EQ(session.advance(2, 0.05).steps, 2);
}

}  // namespace
}  // namespace modeflow
