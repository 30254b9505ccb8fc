#pragma once
/// @file ShippedScenes.h
/// The scene files under scenes/, found when a test runs (a scene added later is covered without
/// touching the tests), and the copy of each that a test can afford to run: the scene itself, or,
/// when its precompute is long, a reduced copy in the test's folder.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "engine/simulation/BackendCapabilities.h"
#include "precompute/PrecomputeMemory.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/CliFixture.h"

namespace modeflow::testing {

inline fs::path scenesFolder() {
    return fs::path(MODEFLOW_SOURCE_DIR) / "scenes";
}

/// Every *.toml under scenes/, relative to it, sorted.
inline std::vector<fs::path> shippedScenes() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::recursive_directory_iterator(scenesFolder()))
        if (entry.is_regular_file() && entry.path().extension() == ".toml")
            scenes.push_back(entry.path().lexically_relative(scenesFolder()));
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

/// "seed_smoke_past_sphere_3d" for seed/smoke_past_sphere_3d.toml: a test name naming the scene.
inline std::string sceneTestName(const fs::path& relative) {
    std::string name = relative.parent_path().empty()
                           ? relative.stem().string()
                           : (relative.parent_path() / relative.stem()).generic_string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

/// The precompute's cost: velocity DOFs × the highest velocity mode. The velocity eigensolve
/// dominates the precompute, and its shift-invert Lanczos iteration takes a few solves per wanted
/// mode. Measured per unit (tests/README.md, "Running the suite"): 3D costs more than 2D, and
/// boxes, with their repeated eigenvalues, most. A closed-form basis has no eigensolve: its sparse
/// coefficients dominate, about 2 N² entries in 3D, so it costs the highest mode squared and the
/// shipped closed-form scenes run at their own size.
inline double precomputeCost(const SceneSpec& scene) {
    const double modes = scene.basis.highestVelocityMode();
    if (hasClosedFormVelocity(scene)) return modes * modes;
    return double(estimatePrecomputeMemory(scene).velocityDofs) * modes;
}

/// Scenes costing more run on a reduced copy (what this allows in seconds: tests/README.md).
inline constexpr double kFullSceneCost = 4e6;
/// What the reduced copy may cost at most: a few seconds.
inline constexpr double kReducedSceneCost = 1e6;
/// The reduced copy keeps at least this many cells per axis.
inline constexpr int kMinReducedCells = 8;

/// `scene` at `factor` of its resolution (each axis, so the bounds and the aspect stay) and of its
/// mode counts: each velocity mode range keeps its place in the spectrum and `factor` of its
/// length, so a frequency-shaped basis keeps its low band, gap and high band.
inline SceneSpec reducedScene(SceneSpec scene, double factor) {
    for (int a = 0; a < scene.grid.dim; ++a)
        scene.grid.resolution[a] =
            std::max(kMinReducedCells, int(std::lround(scene.grid.resolution[a] * factor)));
    std::vector<ModeRange> ranges;
    int previous = 0;
    for (const ModeRange& r : scene.basis.velocityModes) {
        const int first = std::max(previous + 1, int(std::lround((r.first - 1) * factor)) + 1);
        const int count = std::max(1, int(std::lround((r.last - r.first + 1) * factor)));
        ranges.push_back({first, first + count - 1});
        previous = first + count - 1;
    }
    scene.basis.velocityModes = ranges;
    if (scene.basis.scalarModes > 0)
        scene.basis.scalarModes = std::max(1, int(std::lround(scene.basis.scalarModes * factor)));
    return scene;
}

/// "1-58,259-316", as `[basis].modes` reads it.
inline std::string modeListText(const std::vector<ModeRange>& ranges) {
    std::string text;
    for (const ModeRange& r : ranges) {
        if (!text.empty()) text += ',';
        text += std::to_string(r.first) + "-" + std::to_string(r.last);
    }
    return text;
}

/// "[32, 32, 48], modes 1-230, 0 scalar modes", for messages.
inline std::string sizeText(const SceneSpec& scene) {
    std::string text = "[";
    for (int a = 0; a < scene.grid.dim; ++a)
        text += (a ? ", " : "") + std::to_string(scene.grid.resolution[a]);
    return text + "], modes " + modeListText(scene.basis.velocityModes) + ", " +
           std::to_string(scene.basis.scalarModes) + " scalar modes";
}

/// `text` (the scene file of `original`) with [grid].resolution, the [basis] mode keys and
/// [[domain]] mesh files rewritten for `reduced`; mesh files become absolute paths so that they
/// still resolve from the copy's folder. One key per line, as scene files are written; the
/// caller reads the copy back to check it says what was meant.
inline std::string reducedSceneText(const std::string& text, const SceneSpec& original,
                                    const SceneSpec& reduced) {
    static const std::regex keyLine(R"(^\s*([A-Za-z_]+)\s*=.*$)");
    std::istringstream in(text);
    std::ostringstream out;
    std::string line, table;
    int domain = -1;
    for (std::smatch m; std::getline(in, line); out << line << '\n') {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line[start] == '[') {
            table = line.substr(start, line.find_last_of(']', line.find('#')) + 1 - start);
            if (table == "[[domain]]") domain += 1;
            continue;
        }
        if (!std::regex_match(line, m, keyLine)) continue;
        const std::string key = m[1];
        if (table == "[grid]" && key == "resolution") {
            line = "resolution = [";
            for (int a = 0; a < reduced.grid.dim; ++a)
                line += (a ? ", " : "") + std::to_string(reduced.grid.resolution[a]);
            line += "]";
        } else if (table == "[basis]" && key == "velocity_modes") {
            line = "velocity_modes = " + std::to_string(reduced.basis.velocityCount());
        } else if (table == "[basis]" && key == "modes") {
            line = "modes = \"" + modeListText(reduced.basis.velocityModes) + "\"";
        } else if (table == "[basis]" && key == "scalar_modes") {
            line = "scalar_modes = " + std::to_string(reduced.basis.scalarModes);
        } else if (table == "[[domain]]" && key == "file" && domain >= 0 &&
                   domain < int(original.domain.size())) {
            // A TOML literal string: no escapes to get wrong.
            line = "file = '" +
                   fs::absolute(original.domain[domain].meshFile).lexically_normal().string() + "'";
        }
    }
    return out.str();
}

/// The file a test runs for a shipped scene, and what it is.
struct SceneUnderTest {
    SceneSpec original;
    fs::path file;            ///< the scene itself, or its reduced copy
    SceneSpec scene;          ///< what `file` holds
    std::string description;  ///< "NAME: ... full size (...)" or "NAME: ... reduced copy ... from
                              ///< ... to ..."
};

/// The scene at `relative` (under scenes/), or, when its precompute costs more than
/// kFullSceneCost, a copy in `folder` at the largest factor 0.9^k of its resolution and modes
/// that costs at most kReducedSceneCost. The copy keeps the scene's file name, so its outputs
/// are named as the scene's. Fails the test when the copy does not read back as meant.
inline SceneUnderTest sceneUnderTest(const fs::path& relative, const fs::path& folder) {
    SceneUnderTest chosen;
    const fs::path file = scenesFolder() / relative;
    chosen.original = loadScene(file);
    chosen.file = file;
    chosen.scene = chosen.original;
    const double cost = precomputeCost(chosen.original);
    std::ostringstream description;
    description.precision(2);
    description << relative.generic_string() << ": precompute cost " << cost << " DOF·modes";
    if (cost <= kFullSceneCost) {
        chosen.description = description.str() + ", full size (" + sizeText(chosen.original) + ")";
        return chosen;
    }
    double factor = 1.0;
    SceneSpec reduced = chosen.original;
    while (precomputeCost(reduced) > kReducedSceneCost && factor > 0.05) {
        factor *= 0.9;
        reduced = reducedScene(chosen.original, factor);
    }
    EXPECT_LE(precomputeCost(reduced), kReducedSceneCost)
        << "no reduced copy of " << relative << " is cheap enough";
    fs::create_directories(folder);
    chosen.file = folder / relative.filename();
    std::ofstream(chosen.file) << reducedSceneText(slurp(file), chosen.original, reduced);
    chosen.scene = loadScene(chosen.file);
    const SceneSpec& copy = chosen.scene;
    EXPECT_EQ(copy.grid, reduced.grid)
        << "the reduced copy's [grid] reads back otherwise: " << chosen.file;
    EXPECT_EQ(copy.basis, reduced.basis)
        << "the reduced copy's [basis] reads back otherwise: " << chosen.file;
    EXPECT_EQ(copy.domain.size(), chosen.original.domain.size());
    for (std::size_t d = 0; d < std::min(copy.domain.size(), chosen.original.domain.size()); ++d)
        if (copy.domain[d].kind == ShapeKind::Mesh) {
            EXPECT_TRUE(fs::equivalent(copy.domain[d].meshFile, chosen.original.domain[d].meshFile))
                << d;
        }
    description << " > " << kFullSceneCost << ": reduced copy at " << factor
                << " of the size, from " << sizeText(chosen.original) << " to " << sizeText(reduced)
                << " (cost " << precomputeCost(reduced) << ")";
    chosen.description = description.str();
    return chosen;
}

/// The --device values of the backends, every one of which runs every scene.
inline std::vector<std::string> backendOptions() {
    std::vector<std::string> options;
    for (BackendKind kind : kBackends) options.emplace_back(capabilitiesOf(kind).option);
    return options;
}

}  // namespace modeflow::testing
