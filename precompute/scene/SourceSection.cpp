/// @file SourceSection.cpp
/// `[[source]]`: a ball, box or mesh that emits smoke and heat between two times, may drive the
/// air and may move on key frames.

#include <cmath>

#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

SourceSpec readSource(const TomlReader& reader, const toml::table& table, int index) {
    SourceSpec source;
    source.shape = readShape(reader, table, "[[source]]", index, ShapeUse::Source);
    const Section s{table, shapeEntryName("[[source]]", index, source.shape.kind)};
    source.density = readSmokeValue(reader, s, "density", source.density, Sign::NonNegative);
    source.temperature = readSmokeValue(reader, s, "temperature", source.temperature);
    source.fuel = readSmokeValue(reader, s, "fuel", source.fuel, Sign::NonNegative);
    source.start = reader.readNumber(s, "start", source.start, Sign::NonNegative);
    source.end = reader.readNumber(s, "end", source.end, Sign::Positive);
    source.velocity = reader.vector(s, "velocity");
    if (source.velocity) {
        const Vec3& v = *source.velocity;
        const double speed = std::hypot(v[0], v[1], v[2]);  // no overflow in the squares
        if (speed > kMaxInitialSpeed)
            reader.fail(s, "velocity",
                        "speed " + roughNumber(speed) + " is beyond " +
                            roughNumber(kMaxInitialSpeed) + " scene units per unit time",
                        table.get("velocity"));
    }
    source.path = readPath(reader, s, false);
    source.rotation = readRotation(reader, s);
    if (source.shape.kind == ShapeKind::Mesh)
        source.thickness = reader.readNumber(s, "thickness", 0.0, Sign::Positive);
    else if (const toml::node* node = table.get("thickness"))
        reader.fail(s, "thickness", "only a mesh source emits from a shell on its surface", node);
    if (source.end <= source.start)
        reader.fail(s, "end", "must be later than start (" + std::to_string(source.start) + ")",
                    table.get("end"));
    return source;
}

}  // namespace modeflow::scene
