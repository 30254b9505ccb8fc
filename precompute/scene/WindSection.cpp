/// @file WindSection.cpp
/// `[wind]`: the velocity of the air far from solids, blowing through the grid box (round its
/// [[domain]] walls as a potential flow).

#include <cmath>
#include <string>

#include "engine/core/SceneKeywords.h"
#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

WindSpec readWind(const TomlReader& reader, const Section& s, const SceneSpec& scene) {
    reader.checkKeys(s, kWindKeys);
    if (scene.isSurface())
        reader.fail(s.name, "a surface is closed: no wind blows through it", &s.table);
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
    // The wind enters and leaves through the sides along it, which hold it to its own flow; the
    // other sides may be open (an open top over a fire in a breeze).
    for (int a = 0; a < scene.grid.dim; ++a)
        if (v[std::size_t(a)] != 0.0 && scene.grid.opensAxis(a))
            reader.fail(s, "velocity",
                        std::string("the wind blows along ") + axisName(a) +
                            ", whose sides it opens itself: leave " + axisName(a) + "_min and " +
                            axisName(a) + "_max out of [grid].open",
                        s.table.get("velocity"));
    // What comes in with the air, as a source's rates are read.
    wind.density = readSmokeValue(reader, s, "density", 0.0, Sign::NonNegative);
    wind.temperature = readSmokeValue(reader, s, "temperature", 0.0);
    wind.profile =
        reader.readChoice(s, "profile", WindProfile::Uniform, Choices<WindProfile>(kWindProfiles));
    if (wind.profile == WindProfile::Uniform) {
        for (const char* key : {"thickness", "exponent"})
            if (s.table.contains(key))
                reader.fail(s, key, "only a profile = \"boundary-layer\" has one",
                            s.table.get(key));
        return wind;
    }
    // Round [[domain]] walls the held flow is a potential flow, which a layer's shear is not.
    if (!scene.domain.empty())
        reader.fail(s, "profile",
                    "a boundary layer blows through a whole grid box: this scene's [[domain]] "
                    "shapes make walls inside it (blow a uniform wind round them, or stand "
                    "solids in the layer as [[obstacle]]s)",
                    s.table.get("profile"));
    // The floor is the box's low side along the up axis (y in 2D, z in 3D): the layer needs one,
    // and a wind that blows along it.
    const int up = scene.grid.dim - 1;
    if (scene.grid.periodic[std::size_t(up)])
        reader.fail(s, "profile",
                    std::string("a boundary layer grows over the floor, and this scene's ") +
                        (up == 1 ? "y" : "z") + " axis (up) is periodic: it has none",
                    s.table.get("profile"));
    if (scene.grid.open[std::size_t(2 * up)])
        reader.fail(s, "profile",
                    std::string("a boundary layer grows over the floor, and this scene's ") +
                        axisName(up) + "_min is open",
                    s.table.get("profile"));
    if (v[std::size_t(up)] != 0.0)
        reader.fail(s, "velocity",
                    std::string("a boundary layer's wind blows along the floor: its ") +
                        (up == 1 ? "y" : "z") + " (up) component must be 0",
                    s.table.get("velocity"));
    wind.thickness = reader.requireNumber(s, "thickness", Sign::Positive);
    wind.exponent = reader.readNumber(s, "exponent", wind.exponent, Sign::Positive);
    if (wind.exponent > 1.0)
        reader.fail(s, "exponent",
                    "is " + roughNumber(wind.exponent) +
                        "; a boundary layer's power law has an exponent in (0, 1]",
                    s.table.get("exponent"));
    return wind;
}

}  // namespace modeflow::scene
