/// @file SmokeSection.cpp
/// `[smoke]`: buoyancy, the smoke grid's refinement of the basis grid, the advection scheme; and
/// `[fire]`, what burns in it.

#include <cmath>

#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

double readSmokeValue(const TomlReader& reader, const Section& s, std::string_view key,
                      double fallback, Sign sign) {
    const double value = reader.readNumber(s, key, fallback, sign);
    if (std::abs(value) > kMaxSmokeValue)
        reader.fail(s, key,
                    roughNumber(value) + " is beyond " + roughNumber(kMaxSmokeValue) +
                        " in magnitude, the most a smoke value may be (the device holds smoke in "
                        "32-bit floats)",
                    s.table.get(key));
    return value;
}

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
    fire.ignition = readSmokeValue(reader, s, "ignition", fire.ignition);
    fire.burnRate = reader.readNumber(s, "burn_rate", fire.burnRate, Sign::Positive);
    fire.heat = readSmokeValue(reader, s, "heat", fire.heat, Sign::NonNegative);
    fire.smoke = readSmokeValue(reader, s, "smoke", fire.smoke, Sign::NonNegative);
    return fire;
}

}  // namespace modeflow::scene
