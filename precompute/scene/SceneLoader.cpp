/// @file SceneLoader.cpp
/// Scene file → SceneSpec: reads the tables in order (SceneSections.h), each checked for unknown
/// keys before its values are read, and the checks across tables as soon as their tables are
/// read (SceneValidation.h). toml++ is seen only inside precompute/scene.

#include "precompute/scene/SceneLoader.h"

#include <string>

#include "engine/core/InputFile.h"
#include "engine/core/PrintableText.h"
#include "engine/core/RuntimeLimits.h"
#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneValidation.h"
#include "precompute/scene/SceneWording.h"
#include "precompute/scene/TomlReader.h"

namespace modeflow {
namespace {

using namespace scene;

void checkTopLevel(const TomlReader& reader, const toml::table& root) {
    for (const auto& [key, node] : root) {
        const std::string_view name = key.str();
        if (contains(kTopLevelTables, name)) continue;
        std::string what =
            node.is_table() || node.is_array_of_tables() ? "unknown table" : "unknown key";
        if (auto guess = closest(name, kTopLevelTables)) {
            what += " (did you mean " + std::string(*guess) + "?)";
        } else {
            what += " (a scene holds " + joinWords(kTopLevelTables, "and") + ")";
        }
        reader.fail(printableText(name), what, &node);
    }
}

SceneSpec readScene(std::string_view text, const std::filesystem::path& origin) {
    TomlReader reader(origin);
    const toml::table root = reader.parse(text);
    SceneSpec scene;
    scene.sourceFile = origin;
    scene.name = origin.stem().string();

    checkTopLevel(reader, root);
    if (const toml::table* surface = reader.optionalTable(root, "surface")) {
        checkSurfaceSceneTables(reader, root);
        scene.surface = readSurface(reader, {*surface, "[surface]"});
    } else {
        scene.grid = readGrid(reader, {*reader.requireTable(root, "grid"), "[grid]"});
        reader.forEachEntry(root, "domain", [&](const toml::table& t, int index) {
            scene.domain.push_back(readShape(reader, t, "[[domain]]", index, ShapeUse::Domain));
        });
    }
    const Section basis{*reader.requireTable(root, "basis"), "[basis]"};
    if (scene.isSurface()) checkSurfaceBasis(reader, basis);
    scene.basis = readBasis(reader, basis);
    // A surface's discrete spaces are known once its mesh is read (the precompute checks them).
    if (!scene.isSurface()) checkBasisFitsGrid(reader, basis, scene.basis, scene.grid);
    if (const toml::table* t = reader.optionalTable(root, "simulation")) {
        const Section simulation{*t, "[simulation]"};
        scene.simulation = readSimulation(reader, simulation);
        if (scene.isSurface()) checkSurfaceSimulation(reader, simulation, scene.simulation);
    }
    if (const toml::table* t = reader.optionalTable(root, "initial")) {
        const Section initial{*t, "[initial]"};
        // Before reading them, so a field key in a non-MHD scene is named for that.
        checkInitialFieldKeys(reader, initial, scene.simulation);
        if (scene.isSurface()) checkSurfaceInitial(reader, initial);
        scene.initial = readInitial(reader, initial);
        checkInitialFitsBasis(reader, initial, scene.initial, scene.basis);
        // Speeds are measured on the grid's box; a surface's area is known once its mesh is read.
        if (!scene.isSurface()) checkInitialSpeeds(reader, initial, scene.initial, scene.grid);
    }
    checkEntryCount(reader, root, "source", maxSmokeEmitters, "sources");
    reader.forEachEntry(root, "source", [&](const toml::table& t, int index) {
        scene.sources.push_back(readSource(reader, t, index));
    });
    checkEntryCount(reader, root, "obstacle", maxObstacles, "obstacles");
    reader.forEachEntry(root, "obstacle", [&](const toml::table& t, int index) {
        scene.obstacles.push_back(
            readObstacle(reader, {t, "[[obstacle]] #" + std::to_string(index)}));
    });
    if (const toml::table* t = reader.optionalTable(root, "smoke")) {
        const Section smoke{*t, "[smoke]"};
        scene.smoke = readSmoke(reader, smoke);
        checkSmokeGridSize(reader, smoke, scene.smoke, scene.grid);
    }
    if (const toml::table* t = reader.optionalTable(root, "fire")) {
        if (scene.isSurface())
            reader.fail({root, "scene"}, "fire", "a surface scene carries dye, nothing burns", t);
        scene.fire = readFire(reader, {*t, "[fire]"});
    }
    for (std::size_t i = 0; i < scene.sources.size() && !scene.fire; ++i)
        if (scene.sources[i].fuel > 0.0) {
            const toml::table& source = *root["source"].as_array()->at(i).as_table();
            reader.fail({source, "[[source]] #" + std::to_string(i + 1)}, "fuel", kFuelNeedsFire,
                        source.get("fuel"));
        }
    if (const toml::table* t = reader.optionalTable(root, "wind")) {
        scene.wind = readWind(reader, {*t, "[wind]"}, scene);
    }
    checkEntryCount(reader, root, "inflow", maxInflows, "inflows");
    reader.forEachEntry(root, "inflow", [&](const toml::table& t, int index) {
        scene.inflows.push_back(readInflow(reader, t, index, scene));
    });
    if (const toml::table* t = reader.optionalTable(root, "forcing")) {
        const Section forcing{*t, "[forcing]"};
        scene.forcing = readForcing(reader, forcing);
        checkForcingFitsScene(reader, forcing, scene.forcing, scene.basis, scene.simulation);
    }
    if (const toml::table* t = reader.optionalTable(root, "output")) {
        scene.output = readOutput(reader, {*t, "[output]"});
    }
    // After [output] and [simulation]: a rate's particles are counted up to the shot's end.
    checkEntryCount(reader, root, "particles", maxParticleSets, "particle sets");
    const double shotEnd =
        double(scene.output.frames) * scene.output.stepsPerFrame * scene.simulation.dt;
    std::int64_t emitted = 0;
    reader.forEachEntry(root, "particles", [&](const toml::table& t, int index) {
        scene.particles.push_back(readParticleSet(reader, t, index, shotEnd, emitted));
    });
    return scene;
}

}  // namespace

SceneSpec parseScene(std::string_view text, const std::filesystem::path& origin) {
    if (text.size() > kMaxSceneFileBytes)
        throw Error(inputTooLarge(origin.string(), text.size(), "scene file", kMaxSceneFileBytes));
    return readScene(text, origin);
}

SceneSpec loadScene(const std::filesystem::path& file) {
    return parseScene(readInputFile(file, "scene file", kMaxSceneFileBytes), file);
}

}  // namespace modeflow
