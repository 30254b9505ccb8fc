/// @file ShapeSection.cpp
/// `[[domain]]` entries and the shapes of `[[source]]` entries: the shape's own keys, `op` in
/// the domain, and mesh files resolved against the scene's folder.

#include <algorithm>
#include <cctype>
#include <iterator>
#include <system_error>

#include "engine/core/FileKind.h"
#include "engine/core/MeshSequence.h"
#include "engine/core/PrintableText.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneValidation.h"

namespace modeflow::scene {
namespace {

namespace fs = std::filesystem;

/// Paths are longer than keys; 240 characters show any reasonable one whole.
constexpr std::size_t kShownPathChars = 240;

/// Rejects every key the shape does not take, naming the shape when the key belongs to another.
void checkShapeKeys(const TomlReader& reader, const Section& s, ShapeKind kind, ShapeUse use) {
    const bool isDomain = use == ShapeUse::Domain;
    const std::string_view kindName = keywordOf(Choices<ShapeKind>(kShapeKinds), kind);
    // The shape's own keys, plus `shape`, `op` (domain) or the source's or particle set's own.
    std::vector<std::string_view> allowed{"shape"};
    if (isDomain) allowed.push_back("op");
    if (use == ShapeUse::Source)
        allowed.insert(allowed.end(), std::begin(kSourceExtraKeys), std::end(kSourceExtraKeys));
    if (use == ShapeUse::Particles)
        allowed.insert(allowed.end(), std::begin(kParticleExtraKeys), std::end(kParticleExtraKeys));
    if (use == ShapeUse::Inflow)
        allowed.insert(allowed.end(), std::begin(kInflowExtraKeys), std::end(kInflowExtraKeys));
    const auto own = shapeKeys(kind);
    allowed.insert(allowed.end(), own.begin(), own.end());
    for (const auto& [key, node] : s.table) {
        const std::string_view name = key.str();
        if (contains(allowed, name)) continue;
        bool otherShapesKey = false;
        for (const auto& entry : kShapeKinds) {
            otherShapesKey = otherShapesKey || contains(shapeKeys(entry.second), name);
        }
        if (otherShapesKey) {
            reader.fail(s, name,
                        "not a key of a " + std::string(kindName) + " (it takes " +
                            joinWords(own, "and") + ")",
                        &node);
        }
        if (!isDomain && name == "op") {
            reader.fail(s, name, "unknown key (only [[domain]] entries are combined by op)", &node);
        }
        std::string what = "unknown key";
        if (auto guess = closest(name, allowed)) {
            what += " (did you mean " + std::string(*guess) + "?)";
        } else {
            what += " (expected " + joinWords(allowed) + ")";
        }
        reader.fail(s, name, what, &node);
    }
}

}  // namespace

fs::path readMeshFile(const TomlReader& reader, const Section& s, std::string_view key,
                      bool sequence) {
    const std::optional<std::string> file = reader.string(s, key);
    if (!file) reader.fail(s, key, "missing required key");
    if (file->empty()) reader.fail(s, key, "must name an OBJ file, got an empty string");
    fs::path path(*file);
    if (path.is_relative()) path = reader.origin().parent_path() / path;
    path = path.lexically_normal();
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".obj") {
        reader.fail(s, key, "only OBJ meshes are supported, got \"" + printableText(*file) + "\"",
                    s.table.get(key));
    }
    // A sequence's first file must be there; MeshSolids checks the others the run reaches.
    const fs::path first = sequence && isMeshSequence(path) ? sequenceFile(path, 1) : path;
    if (auto why = whyNotARegularFile(first)) {
        const std::string shown = printableText(first.string(), kShownPathChars);
        std::error_code ec;
        reader.fail(s, key,
                    fs::exists(path, ec) ? shown + " " + *why + ", not an OBJ file"
                                         : "no such file: " + shown,
                    s.table.get(key));
    }
    return path;
}

std::string shapeEntryName(const std::string& section, int index, ShapeKind kind) {
    return section + " #" + std::to_string(index) + " (" +
           std::string(keywordOf(Choices<ShapeKind>(kShapeKinds), kind)) + ")";
}

ShapeSpec readShape(const TomlReader& reader, const toml::table& table, const std::string& section,
                    int index, ShapeUse use) {
    const bool isDomain = use == ShapeUse::Domain;
    const std::string entry = section + " #" + std::to_string(index);
    const toml::node* shapeNode = table.get("shape");
    if (shapeNode == nullptr) {
        reader.fail(entry + ".shape",
                    "missing required key (one of " +
                        std::string(isDomain                  ? "ball, box, ellipsoid, cylinder, "
                                                                "torus or mesh"
                                    : use == ShapeUse::Source ? "ball, box or mesh"
                                                              : "ball or box") +
                        ")",
                    &table);
    }
    ShapeSpec shape;
    shape.kind = reader.readChoice(Section{table, entry}, "shape", ShapeKind::Ball,
                                   Choices<ShapeKind>(kShapeKinds));
    const std::string_view kindName = keywordOf(Choices<ShapeKind>(kShapeKinds), shape.kind);
    const Section s{table, shapeEntryName(section, index, shape.kind)};

    if (use == ShapeUse::Source && shape.kind != ShapeKind::Ball && shape.kind != ShapeKind::Box &&
        shape.kind != ShapeKind::Mesh) {
        reader.fail(s, "shape",
                    "a source must be a ball, a box or a mesh, got " + std::string(kindName),
                    shapeNode);
    }
    if ((use == ShapeUse::Particles || use == ShapeUse::Inflow) && shape.kind != ShapeKind::Ball &&
        shape.kind != ShapeKind::Box) {
        reader.fail(
            s, "shape",
            std::string(use == ShapeUse::Particles ? "particles are seeded in" : "an inflow is") +
                " a ball or a box, got " + std::string(kindName),
            shapeNode);
    }
    checkShapeDimension(reader, s, shape.kind, shapeNode);
    checkShapeKeys(reader, s, shape.kind, use);

    const int dim = reader.dimension();
    switch (shape.kind) {
        case ShapeKind::Ball:
            shape.center = reader.requireVector(s, "center");
            shape.radius = reader.requireNumber(s, "radius", Sign::Positive);
            break;
        case ShapeKind::Box: {
            shape.min = reader.requireVector(s, "min");
            shape.max = reader.requireVector(s, "max");
            for (int a = 0; a < dim; ++a) {
                if (!(shape.max[a] > shape.min[a])) {
                    reader.fail(s, "max",
                                std::string("must exceed min on every axis, but on axis ") +
                                    axisName(a) + " min = " + formatNumber(shape.min[a]) +
                                    " and max = " + formatNumber(shape.max[a]),
                                table.get("max"));
                }
            }
            break;
        }
        case ShapeKind::Ellipsoid:
            shape.center = reader.requireVector(s, "center");
            shape.radii = reader.requireVector(s, "radii");
            for (int a = 0; a < dim; ++a) {
                if (!(shape.radii[a] > 0.0)) {
                    reader.fail(s, "radii",
                                std::string("must be > 0 on every axis, got ") +
                                    formatNumber(shape.radii[a]) + " on axis " + axisName(a),
                                table.get("radii"));
                }
            }
            break;
        case ShapeKind::Cylinder:
            shape.center = reader.requireVector(s, "center");
            shape.radius = reader.requireNumber(s, "radius", Sign::Positive);
            shape.halfHeight = reader.requireNumber(s, "half_height", Sign::Positive);
            break;
        case ShapeKind::Torus:
            shape.center = reader.requireVector(s, "center");
            shape.majorRadius = reader.requireNumber(s, "major_radius", Sign::Positive);
            shape.minorRadius = reader.requireNumber(s, "minor_radius", Sign::Positive);
            if (!(shape.minorRadius < shape.majorRadius)) {
                reader.fail(s, "minor_radius",
                            "must be less than major_radius (" + formatNumber(shape.majorRadius) +
                                "), got " + formatNumber(shape.minorRadius),
                            table.get("minor_radius"));
            }
            break;
        case ShapeKind::Mesh:
            shape.meshFile = readMeshFile(reader, s, "file");
            break;
    }

    if (isDomain) {
        const Choices<CsgOp> ops(kCsgOps);
        shape.op = reader.readChoice(s, "op", CsgOp::Union, ops);
        // The first shape starts the domain; subtracting from or intersecting with nothing
        // is almost surely a forgotten first entry, not an intent.
        if (index == 1 && shape.op != CsgOp::Union) {
            reader.fail(s, "op",
                        "the first [[domain]] entry starts the domain, so it cannot " +
                            std::string(keywordOf(ops, shape.op)) + "; put the shape to " +
                            std::string(keywordOf(ops, shape.op)) +
                            " from first (e.g. a box covering the grid)",
                        table.get("op"));
        }
    }
    return shape;
}

}  // namespace modeflow::scene
