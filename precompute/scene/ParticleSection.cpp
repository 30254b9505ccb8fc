/// @file ParticleSection.cpp
/// `[[particles]]`: a set of points the air carries, seeded in a ball or a box, all at once or at
/// a rate, tracers or inertial.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine/core/RuntimeLimits.h"
#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

ParticleSetSpec readParticleSet(const TomlReader& reader, const toml::table& table, int index,
                                double shotEnd, std::int64_t& emitted) {
    ParticleSetSpec set;
    set.region = readShape(reader, table, "[[particles]]", index, ShapeUse::Particles);
    const Section s{table, shapeEntryName("[[particles]]", index, set.region.kind)};
    const toml::node* count = table.get("count");
    const toml::node* rate = table.get("rate");
    if ((count == nullptr) == (rate == nullptr))
        reader.fail(s, count ? "rate" : "count",
                    count ? "give count (particles at start) or rate (per unit time), not both"
                          : "missing: give count (particles at start) or rate (per unit time)",
                    count ? rate : &table);
    set.start = reader.readNumber(s, "start", set.start, Sign::NonNegative);
    double emits = 0.0;
    if (count) {
        set.count = *reader.integer(s, "count", 1, maxParticles);
        if (const toml::node* end = table.get("end"))
            reader.fail(s, "end",
                        "a set of count particles is seeded once, at start; end "
                        "belongs to a set emitting at a rate",
                        end);
        emits = double(set.count);
    } else {
        set.rate = reader.requireNumber(s, "rate", Sign::Positive);
        set.end = reader.readNumber(s, "end", set.end, Sign::Positive);
        if (set.end <= set.start)
            reader.fail(s, "end", "must be later than start (" + formatNumber(set.start) + ")",
                        table.get("end"));
        emits = std::floor(set.rate * std::max(0.0, std::min(set.end, shotEnd) - set.start));
    }
    if (emits + double(emitted) > double(maxParticles))
        reader.fail(s, count ? "count" : "rate",
                    "the scene's sets would emit " + roughNumber(emits + double(emitted)) +
                        " particles by its last frame, at most " + std::to_string(maxParticles) +
                        " fit",
                    count ? count : rate);
    emitted += std::int64_t(emits);
    set.drag = reader.readNumber(s, "drag", set.drag, Sign::NonNegative);
    if (set.drag > 0.0) {
        set.gravity = reader.readNumber(s, "gravity", set.gravity);
        // What an inertial particle falls at in still air.
        if (std::abs(set.gravity) / set.drag > kMaxInitialSpeed)
            reader.fail(
                s, "gravity",
                "falls at gravity / drag = " + roughNumber(std::abs(set.gravity) / set.drag) +
                    " in still air, beyond " + roughNumber(kMaxInitialSpeed) +
                    " scene units per unit time",
                table.get("gravity") ? table.get("gravity") : table.get("drag"));
    } else if (const toml::node* gravity = table.get("gravity")) {
        reader.fail(s, "gravity",
                    "acts on inertial particles only (drag > 0); tracers (drag = 0) "
                    "move with the air",
                    gravity);
    }
    if (table.get("seed"))
        set.seed =
            std::uint64_t(*reader.integer(s, "seed", 0, std::numeric_limits<std::int64_t>::max()));
    return set;
}

}  // namespace modeflow::scene
