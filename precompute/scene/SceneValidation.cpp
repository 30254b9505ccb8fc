/// @file SceneValidation.cpp

#include "precompute/scene/SceneValidation.h"

#include <cstdint>

#include "precompute/scene/SceneLoader.h"

namespace modeflow::scene {

void checkShapeDimension(const TomlReader& reader, const Section& shape, ShapeKind kind,
                         const toml::node* shapeNode) {
    if (reader.dimension() == 2 &&
        (kind == ShapeKind::Cylinder || kind == ShapeKind::Torus || kind == ShapeKind::Mesh)) {
        reader.fail(shape, "shape",
                    "a " + std::string(keywordOf(Choices<ShapeKind>(kShapeKinds), kind)) +
                        " is 3D only, but this scene is 2D ([grid].resolution has 2 entries)",
                    shapeNode);
    }
}

void checkBasisFitsGrid(const TomlReader& reader, const Section& s, const BasisSpec& basis,
                        const GridSpec& grid) {
    // A cheap upper bound on the discrete spaces: more faces (cells) than modes asked for,
    // whatever the domain. The exact count is known only after the geometry is built.
    std::int64_t cells = 1;
    for (int a = 0; a < grid.dim; ++a) cells *= grid.resolution[a];
    std::int64_t faces = 0;
    for (int a = 0; a < grid.dim; ++a)
        faces += cells / grid.resolution[a] * (grid.resolution[a] + 1);
    if (basis.highestVelocityMode() > faces) {
        const toml::node* countNode = s.table.get("velocity_modes");
        reader.fail(s, countNode != nullptr ? "velocity_modes" : "modes",
                    "mode " + std::to_string(basis.highestVelocityMode()) +
                        " is beyond the discrete space: the grid has only " +
                        std::to_string(faces) + " faces",
                    countNode != nullptr ? countNode : s.table.get("modes"));
    }
    if (basis.scalarModes > cells) {
        reader.fail(s, "scalar_modes",
                    std::to_string(basis.scalarModes) +
                        " is beyond the discrete space: the grid has only " +
                        std::to_string(cells) + " cells",
                    s.table.get("scalar_modes"));
    }
}

void checkInitialFieldKeys(const TomlReader& reader, const Section& s,
                           const SimulationSpec& simulation) {
    if (simulation.mhd) return;
    for (std::string_view key : kInitialFieldKeys)
        if (s.table.contains(key))
            reader.fail(s, key, "only used with [simulation] mhd = true", s.table.get(key));
}

void checkInitialFitsBasis(const TomlReader& reader, const Section& s, const InitialSpec& initial,
                           const BasisSpec& basis) {
    // The file's own numbers (the reader has checked their types), not the narrowed ones.
    const int modeCount = basis.velocityCount();
    if (initial.band) {
        const toml::node* node = s.table.get("band");
        const std::int64_t last = (*node->as_array())[1].as_integer()->get();
        if (last > modeCount) {
            reader.fail(s, "band",
                        "mode " + std::to_string(last) + " is beyond the basis ([basis] has " +
                            std::to_string(modeCount) + " velocity modes)",
                        node);
        }
    }
    if (!initial.amplitudes.empty()) {
        const toml::array& array = *s.table.get("amplitudes")->as_array();
        for (std::size_t e = 0; e < array.size(); ++e) {
            const toml::node& entry = array[e];
            const std::int64_t mode = (*entry.as_array())[0].as_integer()->get();
            if (mode < 1 || mode > modeCount) {
                reader.fail(s.name + ".amplitudes[" + std::to_string(e) + "]",
                            "mode " + std::to_string(mode) + " is outside the basis (modes 1 to " +
                                std::to_string(modeCount) + ")",
                            &entry);
            }
        }
    }
}

void checkSmokeGridSize(const TomlReader& reader, const Section& s, const SmokeSpec& smoke,
                        const GridSpec& grid) {
    std::int64_t cells = 1;
    for (int a = 0; a < grid.dim; ++a) {
        cells *= std::int64_t{grid.resolution[a]} * smoke.resolutionScale;
    }
    if (cells > kMaxSmokeCells) {
        reader.fail(s, "resolution_scale",
                    "a smoke grid of " + std::to_string(cells) +
                        " cells is absurdly large (the limit is 2^31 cells)",
                    s.table.get("resolution_scale"));
    }
}

void checkEntryCount(const TomlReader& reader, const toml::table& root, std::string_view name,
                     int limit, std::string_view what) {
    const toml::node* node = root.get(name);
    const toml::array* entries = node != nullptr ? node->as_array() : nullptr;
    if (entries == nullptr || entries->size() <= static_cast<std::size_t>(limit)) return;
    reader.fail("[[" + std::string(name) + "]]",
                std::to_string(entries->size()) + " entries; at most " + std::to_string(limit) +
                    " " + std::string(what) + " take part in a simulation",
                &(*entries)[static_cast<std::size_t>(limit)]);
}

}  // namespace modeflow::scene
