#include "tests/support/SurfaceRuns.h"

#include "precompute/Precompute.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tests/support/TestFolder.h"

namespace modeflow::testing {

RunInputs icosphereRun(const IcosphereRunSpec& spec) {
    static TestFolder folder;
    writeObj(folder / "sphere.obj", makeIcosphere(3));
    SceneSpec scene;
    scene.name = "sphere";
    scene.surface = SurfaceSpec{folder / "sphere.obj"};
    scene.basis.velocityModes = {{1, spec.velocityModes}};
    scene.basis.scalarModes = spec.scalarModes;
    scene.simulation.dt = 0.02;
    scene.simulation.viscosity = spec.viscosity;
    scene.output.stepsPerFrame = 2;
    SourceSpec source;
    source.shape.center = {0.0, 0.0, 1.0};
    source.shape.radius = 0.3;
    source.density = 1.0;
    source.end = spec.sourceEnd;
    scene.sources.push_back(source);
    Progress quiet = Progress::silent();
    RunInputs run = prepareRun(scene, computeBasis(scene, quiet), RunParts::Dynamics);
    run.initialVelocity.setZero();
    return run;
}

}  // namespace modeflow::testing
