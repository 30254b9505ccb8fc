/// @file SmokeSection.cpp
/// `[smoke]`: buoyancy, the smoke grid's refinement of the basis grid, the advection scheme.

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

SmokeSpec readSmoke(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kSmokeKeys);
    SmokeSpec smoke;
    smoke.buoyancy = reader.readNumber(s, "buoyancy", smoke.buoyancy);
    smoke.resolutionScale = reader.readInt(s, "resolution_scale", smoke.resolutionScale, 1, 8);
    smoke.advection = reader.readChoice(s, "advection", smoke.advection,
                                        Choices<AdvectionScheme>(kAdvectionSchemes));
    return smoke;
}

}  // namespace modeflow::scene
