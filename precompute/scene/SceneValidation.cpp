/// @file SceneValidation.cpp

#include "precompute/scene/SceneValidation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

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
        faces += cells / grid.resolution[a] * (grid.resolution[a] + (grid.isPeriodic(a) ? 0 : 1));
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

void checkForcingFitsScene(const TomlReader& reader, const Section& s, const ForcingSpec& forcing,
                           const BasisSpec& basis, const SimulationSpec& simulation) {
    if (simulation.mhd)
        reader.fail(s.name,
                    "holds velocity modes of the fluid model; it cannot be combined with "
                    "[simulation] mhd = true",
                    &s.table);
    const int modeCount = basis.velocityCount();
    for (const ModeRange& range : forcing.holdModes)
        if (range.last > modeCount)
            reader.fail(s, "hold_modes",
                        "mode " + std::to_string(range.last) +
                            " is beyond the basis ([basis] has " + std::to_string(modeCount) +
                            " velocity modes)",
                        s.table.get("hold_modes"));
    // However the list splits them ("1-5,6-12"): its ranges are sorted and disjoint (ModeList).
    long long held = 0;
    for (const ModeRange& range : forcing.holdModes) held += range.last - range.first + 1;
    if (!forcing.holdModes.empty() && held >= modeCount)
        reader.fail(s, "hold_modes", "holds every mode of the basis: nothing would move",
                    s.table.get("hold_modes"));
}

void checkInitialSpeeds(const TomlReader& reader, const Section& s, const InitialSpec& initial,
                        const GridSpec& grid) {
    // Energies are ½∫|u|² dV (the basis is ⋆-orthonormal); 2D grids are one unit deep.
    double volume = 1.0, longest = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double side = grid.boundsMax[a] - grid.boundsMin[a];
        volume *= side;
        if (a < grid.dim) longest = std::max(longest, side);
    }
    const auto meanOf = [&](double energy) { return std::sqrt(2.0 * energy / volume); };
    const std::string limit =
        "; at most " + roughNumber(kMaxInitialSpeed) + " scene units per unit time";
    const auto checkEnergy = [&](std::string_view key, double energy, std::string_view what,
                                 std::string_view mean) {
        if (!(meanOf(energy) > kMaxInitialSpeed)) return;
        reader.fail(s, key,
                    std::string(what) + " is a mean " + std::string(mean) + " of " +
                        roughNumber(meanOf(energy)) + " (sqrt(2 energy / grid volume " +
                        roughNumber(volume) + "))" + limit,
                    s.table.get(key));
    };
    if (s.table.contains("energy"))
        checkEnergy("energy", initial.energy, roughNumber(initial.energy), "speed");
    if (!initial.amplitudes.empty()) {
        double energy = 0.0;
        for (const auto& [mode, amplitude] : initial.amplitudes)
            energy += 0.5 * amplitude * amplitude;
        checkEnergy("amplitudes", energy, "½Σa² = " + roughNumber(energy), "speed");
    }
    if (s.table.contains("magnetic_energy"))
        checkEnergy("magnetic_energy", initial.magneticEnergy, roughNumber(initial.magneticEnergy),
                    "field");
    if (s.table.contains("magnetic_strength") && initial.magneticStrength > kMaxInitialSpeed)
        reader.fail(s, "magnetic_strength",
                    roughNumber(initial.magneticStrength) + " is beyond " +
                        roughNumber(kMaxInitialSpeed) + " (scene units per unit time)",
                    s.table.get("magnetic_strength"));
    // A circulation is a speed times a length.
    const double maxStrength = kMaxInitialSpeed * longest;
    for (std::size_t v = 0; v < initial.vortices.size(); ++v) {
        const double strength = initial.vortices[v].strength;
        if (!(std::abs(strength) > maxStrength)) continue;
        const toml::node& entry = (*s.table.get("vortex")->as_array())[v];
        reader.fail("[[initial.vortex]] #" + std::to_string(v + 1) + ".strength",
                    "magnitude " + roughNumber(std::abs(strength)) + " is beyond " +
                        roughNumber(maxStrength) + " (" + roughNumber(kMaxInitialSpeed) +
                        " scene units per unit time times the grid's longest side, " +
                        formatNumber(longest) + ")",
                    entry.as_table()->get("strength"));
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
