/// @file VortexSection.cpp
/// `[[initial.vortex]]`: Gaussian-cored point vortices in 2D, vortex rings in 3D.

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

std::vector<VortexSpec> readVortices(const TomlReader& reader, const Section& s) {
    const toml::node* node = s.table.get("vortex");
    const std::string where = "[[initial.vortex]]";
    if (node == nullptr) {
        reader.fail(where, "missing: velocity = \"vortices\" needs at least one [[initial.vortex]]",
                    &s.table);
    }
    const toml::array* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables() || array->empty()) {
        reader.fail(
            where,
            "expected an array of tables (write [[initial.vortex]]), got " + describeType(*node),
            node);
    }
    const int dim = reader.dimension();
    const auto keys = dim == 2 ? std::span<const std::string_view>(kVortexKeys2d)
                               : std::span<const std::string_view>(kVortexKeys3d);
    std::vector<VortexSpec> out;
    int index = 0;
    for (const toml::node& entry : *array) {
        ++index;
        const Section v{*entry.as_table(), where + " #" + std::to_string(index)};
        for (const auto& [key, value] : v.table) {
            if (dim == 2 && (key.str() == "normal" || key.str() == "ring_radius")) {
                reader.fail(v, key.str(),
                            "only 3D vortex rings take it, but this scene is 2D "
                            "([grid].resolution has 2 entries)",
                            &value);
            }
        }
        reader.checkKeys(v, keys);
        VortexSpec vortex;
        vortex.center = reader.requireVector(v, "center");
        if (!v.table.contains("strength")) reader.fail(v, "strength", "missing required key");
        vortex.strength = reader.readNumber(v, "strength", 0.0);
        vortex.radius = reader.requireNumber(v, "radius", Sign::Positive);
        if (dim == 3) {
            vortex.normal = reader.requireVector(v, "normal");
            const Vec3& n = vortex.normal;
            if (!(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0.0)) {
                reader.fail(v, "normal", "must be a non-zero vector", v.table.get("normal"));
            }
            vortex.ringRadius = reader.requireNumber(v, "ring_radius", Sign::Positive);
        }
        out.push_back(vortex);
    }
    return out;
}

}  // namespace modeflow::scene
