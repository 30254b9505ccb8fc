/// @file WindSection.cpp
/// `[wind]`: the velocity of the air far from solids, blowing through a whole grid box.

#include <cmath>

#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

WindSpec readWind(const TomlReader& reader, const Section& s, const SceneSpec& scene) {
    reader.checkKeys(s, kWindKeys);
    if (scene.isSurface())
        reader.fail(s.name, "a surface is closed: no wind blows through it", &s.table);
    // The base flow is the constant U only on a whole box; around [[domain]] solids it is a
    // potential flow, not built yet.
    if (!scene.domain.empty())
        reader.fail(s.name,
                    "the wind blows through a whole grid box: this scene's [[domain]] shapes "
                    "make walls inside it; stand solids in the wind as [[obstacle]]s",
                    &s.table);
    if (scene.simulation.mhd)
        reader.fail(s.name, "a wind does not carry a magnetic field ([simulation] mhd)", &s.table);
    WindSpec wind;
    wind.velocity = reader.requireVector(s, "velocity");
    const Vec3& v = wind.velocity;
    const double speed = std::hypot(v[0], v[1], v[2]);  // no overflow in the squares
    if (!(speed <= kMaxInitialSpeed))
        reader.fail(s, "velocity",
                    "speed " + roughNumber(speed) + " is beyond " + roughNumber(kMaxInitialSpeed) +
                        " scene units per unit time",
                    s.table.get("velocity"));
    return wind;
}

}  // namespace modeflow::scene
