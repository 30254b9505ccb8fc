/// @file ObstacleSection.cpp
/// `[[obstacle]]`: a ball, box or capsule moving along key frames.

#include "precompute/scene/SceneSections.h"

namespace modeflow::scene {

ObstacleSpec readObstacle(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kObstacleKeys);
    if (!s.table.contains("shape"))
        reader.fail(s, "shape", "missing required key (one of ball, box or capsule)");
    const Choices<ObstacleShape> shapes(kObstacleShapes);
    ObstacleSpec obstacle;
    obstacle.shape = reader.readChoice(s, "shape", obstacle.shape, shapes);
    const auto unused = [&](std::string_view key) {
        if (s.table.contains(key))
            reader.fail(s, key, "not used by a " + std::string(keywordOf(shapes, obstacle.shape)),
                        s.table.get(key));
    };
    const int dim = reader.dimension();
    if (obstacle.shape == ObstacleShape::Box) {
        obstacle.halfSize = reader.requireVector(s, "half_size");
        for (int a = 0; a < dim; ++a)
            if (!(obstacle.halfSize[a] > 0.0))
                reader.fail(s, "half_size", "every entry must be > 0", s.table.get("half_size"));
        unused("radius");
        unused("axis");
    } else {
        obstacle.radius = reader.requireNumber(s, "radius", Sign::Positive);
        unused("half_size");
        if (obstacle.shape == ObstacleShape::Capsule)
            obstacle.axis = reader.requireVector(s, "axis");
        else
            unused("axis");
    }
    const toml::node* node = s.table.get("path");
    const std::string where = s.name + ".path";
    const toml::array* path = node ? node->as_array() : nullptr;
    if (path == nullptr || path->empty())
        reader.fail(
            where,
            "expected an array of key frames [t, x, y" + std::string(dim == 3 ? ", z" : "") + "]",
            node ? node : &s.table);
    for (const toml::node& entry : *path) {
        const toml::array* frame = entry.as_array();
        if (frame == nullptr || frame->size() != std::size_t(dim + 1))
            reader.fail(where,
                        "each key frame is " + std::to_string(dim + 1) + " numbers [t, position]",
                        &entry);
        const double t = reader.numberValue((*frame)[0], where + " time");
        Vec3 position{0.0, 0.0, 0.0};
        for (int a = 0; a < dim; ++a)
            position[a] = reader.numberValue((*frame)[std::size_t(a + 1)], where);
        if (!obstacle.path.empty() && !(t > obstacle.path.back().first))
            reader.fail(where, "key frame times must increase", &entry);
        obstacle.path.emplace_back(t, position);
    }
    return obstacle;
}

}  // namespace modeflow::scene
