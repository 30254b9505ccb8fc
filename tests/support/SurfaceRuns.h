#pragma once
/// @file SurfaceRuns.h
/// A surface scene's run for the engine tests: the unit icosphere of 642 vertices with a dye
/// source at the north pole, prepared as `run` prepares it.

#include "tools/compose/RunPreparation.h"

namespace modeflow::testing {

struct IcosphereRunSpec {
    int velocityModes = 15;  ///< modes 1 … velocityModes
    int scalarModes = 35;
    double viscosity = 0.0;
    double sourceEnd = 0.4;  ///< the source (radius 0.3, density 1) emits until then
};

/// The run (dt 0.02, 2 steps a frame), its initial velocity zero; the mesh is written to a folder
/// of the process's own.
RunInputs icosphereRun(const IcosphereRunSpec& spec);

}  // namespace modeflow::testing
