/// @file SmokeSection.cpp
/// `[smoke]`: buoyancy, the smoke grid's refinement of the basis grid, the advection scheme; and
/// `[fire]`, what burns in it.

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

namespace modeflow::scene {

FireSpec readFire(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kFireKeys);
    FireSpec fire;
    fire.ignition = reader.readNumber(s, "ignition", fire.ignition);
    fire.burnRate = reader.readNumber(s, "burn_rate", fire.burnRate, Sign::Positive);
    fire.heat = reader.readNumber(s, "heat", fire.heat, Sign::NonNegative);
    fire.smoke = reader.readNumber(s, "smoke", fire.smoke, Sign::NonNegative);
    return fire;
}

}  // namespace modeflow::scene
