/// @file ObstacleSection.cpp
/// `[[obstacle]]`: a ball, box, capsule or closed mesh moving and turning along key frames.

#include <cmath>

#include "engine/core/MeshSequence.h"
#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow::scene {

std::vector<RotationKey> readRotation(const TomlReader& reader, const Section& s) {
    std::vector<RotationKey> keys;
    const toml::node* node = s.table.get("rotation");
    if (node == nullptr) return keys;
    const std::string where = s.name + ".rotation";
    const toml::array* frames = node->as_array();
    if (frames == nullptr || frames->empty())
        reader.fail(where, "expected an array of key frames [t, ax, ay, az, degrees]", node);
    for (const toml::node& entry : *frames) {
        const toml::array* frame = entry.as_array();
        if (frame == nullptr || frame->size() != 5)
            reader.fail(where, "each key frame is 5 numbers [t, ax, ay, az, degrees]", &entry);
        RotationKey key;
        key.time = reader.numberValue((*frame)[0], where + " time");
        double length2 = 0.0;
        for (int a = 0; a < 3; ++a) {
            key.axis[a] = reader.numberValue((*frame)[std::size_t(a + 1)], where + " axis");
            length2 += key.axis[a] * key.axis[a];
        }
        key.degrees = reader.numberValue((*frame)[4], where + " degrees");
        if (!(length2 > 0.0) || !std::isfinite(length2))
            reader.fail(where, "the axis [ax, ay, az] must have a non-zero, finite length", &entry);
        for (double& component : key.axis) component /= std::sqrt(length2);
        if (reader.dimension() == 2 && (key.axis[0] != 0.0 || key.axis[1] != 0.0))
            reader.fail(where, "a 2D obstacle turns about z: the axis must be [0, 0, ±1]", &entry);
        if (!keys.empty() && !(key.time > keys.back().time))
            reader.fail(where, "key frame times must increase", &entry);
        if (!keys.empty() && std::abs(key.degrees - keys.back().degrees) * M_PI / 180.0 >
                                 kMaxInitialSpeed * (key.time - keys.back().time))
            reader.fail(where,
                        "turns faster than " + roughNumber(kMaxInitialSpeed) +
                            " radians per unit time from the key frame before",
                        &entry);
        keys.push_back(key);
    }
    return keys;
}

std::vector<std::pair<double, Vec3>> readPath(const TomlReader& reader, const Section& s,
                                              bool required) {
    std::vector<std::pair<double, Vec3>> keys;
    const toml::node* node = s.table.get("path");
    if (node == nullptr && !required) return keys;
    const int dim = reader.dimension();
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
        if (!keys.empty() && !(t > keys.back().first))
            reader.fail(where, "key frame times must increase", &entry);
        if (!keys.empty()) {
            const Vec3& from = keys.back().second;
            const double distance =
                std::hypot(position[0] - from[0], position[1] - from[1], position[2] - from[2]);
            if (distance > kMaxInitialSpeed * (t - keys.back().first))
                reader.fail(where,
                            "moves faster than " + roughNumber(kMaxInitialSpeed) +
                                " scene units per unit time from the key frame before",
                            &entry);
        }
        keys.emplace_back(t, position);
    }
    return keys;
}

ObstacleSpec readObstacle(const TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kObstacleKeys);
    if (!s.table.contains("shape"))
        reader.fail(s, "shape", "missing required key (one of ball, box, capsule or mesh)");
    const Choices<ObstacleShape> shapes(kObstacleShapes);
    ObstacleSpec obstacle;
    obstacle.shape = reader.readChoice(s, "shape", obstacle.shape, shapes);
    const auto unused = [&](std::string_view key) {
        if (s.table.contains(key))
            reader.fail(s, key, "not used by a " + std::string(keywordOf(shapes, obstacle.shape)),
                        s.table.get(key));
    };
    const int dim = reader.dimension();
    if (obstacle.shape != ObstacleShape::Mesh) {
        unused("file");
        unused("scale");
        unused("sequence_rate");
    }
    if (obstacle.shape == ObstacleShape::Mesh) {
        unused("radius");
        unused("half_size");
        unused("axis");
        obstacle.meshFile = readMeshFile(reader, s, "file", true);
        obstacle.scale = reader.readNumber(s, "scale", 1.0, Sign::Positive);
        if (isMeshSequence(obstacle.meshFile)) {
            if (!s.table.contains("sequence_rate"))
                reader.fail(s, "sequence_rate",
                            "missing required key: `file` names a numbered sequence (its '#')");
            obstacle.sequenceRate = reader.readNumber(s, "sequence_rate", 0.0, Sign::Positive);
            if (obstacle.sequenceRate > kMaxSequenceRate)
                reader.fail(s, "sequence_rate",
                            "at most " + roughNumber(kMaxSequenceRate) + " files per unit time",
                            s.table.get("sequence_rate"));
        } else if (s.table.contains("sequence_rate")) {
            reader.fail(s, "sequence_rate",
                        "only for a numbered sequence of files (a file name with ####)",
                        s.table.get("sequence_rate"));
        }
    } else if (obstacle.shape == ObstacleShape::Box) {
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
    obstacle.path = readPath(reader, s, true);
    obstacle.rotation = readRotation(reader, s);
    return obstacle;
}

}  // namespace modeflow::scene
