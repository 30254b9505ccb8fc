/// @file SceneSchema.cpp
/// The per-choice key lists, and the public keyword functions of SceneLoader.h.

#include "precompute/scene/SceneSchema.h"

#include <string>
#include <vector>

#include "engine/core/PrintableText.h"
#include "precompute/scene/SceneLoader.h"
#include "precompute/scene/SceneWording.h"

namespace modeflow {
namespace scene {

std::span<const std::string_view> initialKeys(InitialVelocity velocity) {
    static constexpr std::string_view random[] = {"energy", "seed", "band"};
    static constexpr std::string_view modes[] = {"amplitudes"};
    static constexpr std::string_view vortices[] = {"vortex", "energy"};
    switch (velocity) {
        case InitialVelocity::Zero:
            return {};
        case InitialVelocity::Random:
            return random;
        case InitialVelocity::Modes:
            return modes;
        case InitialVelocity::Vortices:
            return vortices;
    }
    return {};
}

std::span<const std::string_view> magneticKeys(InitialMagnetic magnetic) {
    static constexpr std::string_view random[] = {"magnetic_energy", "magnetic_seed"};
    static constexpr std::string_view uniform[] = {"magnetic_direction", "magnetic_strength",
                                                   "magnetic_wall_layer"};
    return magnetic == InitialMagnetic::Uniform ? std::span<const std::string_view>(uniform)
                                                : std::span<const std::string_view>(random);
}

std::span<const std::string_view> shapeKeys(ShapeKind kind) {
    static constexpr std::string_view ball[] = {"center", "radius"};
    static constexpr std::string_view box[] = {"min", "max"};
    static constexpr std::string_view ellipsoid[] = {"center", "radii"};
    static constexpr std::string_view cylinder[] = {"center", "radius", "half_height"};
    static constexpr std::string_view torus[] = {"center", "major_radius", "minor_radius"};
    static constexpr std::string_view mesh[] = {"file"};
    switch (kind) {
        case ShapeKind::Ball:
            return ball;
        case ShapeKind::Box:
            return box;
        case ShapeKind::Ellipsoid:
            return ellipsoid;
        case ShapeKind::Cylinder:
            return cylinder;
        case ShapeKind::Torus:
            return torus;
        case ShapeKind::Mesh:
            return mesh;
    }
    return {};
}

}  // namespace scene

Integrator parseIntegrator(std::string_view text, std::string_view key) {
    std::vector<std::string_view> names;
    for (const auto& [name, value] : scene::kIntegrators) {
        if (name == text) return value;
        names.push_back(name);
    }
    std::string what = std::string(key) + ": unknown integrator \"" + printableText(text) + "\"";
    if (auto guess = scene::closest(text, names))
        what += " (did you mean " + std::string(*guess) + "?)";
    throw Error(what + "; expected " + scene::joinWords(names));
}

}  // namespace modeflow
