/// @file SurfaceSection.cpp
/// `[surface]`: a surface scene's mesh, and what a surface scene may not hold (the grid's tables
/// and keys). The mesh itself is read and checked by the precompute (precompute/surface), as
/// [[domain]] meshes are.

#include <string>

#include "precompute/scene/SceneSections.h"
#include "precompute/scene/SceneValidation.h"

namespace modeflow::scene {

SurfaceSpec readSurface(TomlReader& reader, const Section& s) {
    reader.checkKeys(s, kSurfaceKeys);
    SurfaceSpec surface;
    surface.meshFile = readMeshFile(reader, s, "mesh");
    reader.setDimension(3);  // sources' centres and corners are points in space
    return surface;
}

void checkSurfaceSceneTables(const TomlReader& reader, const toml::table& root) {
    for (std::string_view grid : {"grid", "domain"}) {
        if (const toml::node* node = root.get(grid)) {
            reader.fail(grid == "grid" ? "[grid]" : "[[domain]]",
                        "a scene is either a grid scene ([grid], [[domain]]) or a surface scene "
                        "([surface]), not both; remove [surface] or the grid's tables",
                        node);
        }
    }
    if (const toml::node* node = root.get("obstacle"))
        reader.fail("[[obstacle]]",
                    "moving obstacles push on a grid's faces; a surface scene ([surface]) has none",
                    node);
    if (const toml::node* node = root.get("inflow"))
        reader.fail("[[inflow]]", "a surface is closed: no air comes in through it", node);
    if (const toml::node* node = root.get("particles"))
        reader.fail("[[particles]]",
                    "particles are carried by a grid's velocity; a surface scene ([surface]) has "
                    "none",
                    node);
    const toml::array* sources = root.get("source") ? root.get("source")->as_array() : nullptr;
    for (std::size_t i = 0; sources && i < sources->size(); ++i) {
        const toml::table* source = (*sources)[i].as_table();
        if (!source) continue;
        const std::string entry = "[[source]] #" + std::to_string(i + 1);
        if (const toml::node* node = source->get("velocity"))
            reader.fail(entry + ".velocity",
                        "a surface scene's sources add dye alone; driving the air belongs to grid "
                        "scenes",
                        node);
        for (const char* key : {"path", "rotation"})
            if (const toml::node* node = source->get(key))
                reader.fail(entry + "." + key,
                            "a surface scene's sources stay still; moving sources belong to grid "
                            "scenes",
                            node);
        const toml::node* shape = source->get("shape");
        if (shape && shape->value<std::string>() == "mesh")
            reader.fail(entry + ".shape",
                        "a surface scene's sources are balls or boxes in space; mesh sources fill "
                        "a grid's cells",
                        shape);
    }
    if (const toml::node* node = root.get("smoke"))
        reader.fail("[smoke]",
                    "buoyancy and the smoke grid belong to grid scenes; a surface scene carries "
                    "the dye of its [[source]] entries in its scalar basis instead",
                    node);
}

void checkSurfaceBasis(const TomlReader& reader, const Section& s) {
    for (std::string_view key : kGridBasisKeys) {
        if (const toml::node* node = s.table.get(key))
            reader.fail(s, key,
                        "only for grid scenes: a closed surface has no wall, and its basis has "
                        "no cut cells",
                        node);
    }
    // The tensor-free advection evaluates the grid's vorticity quadrature; a surface's
    // coefficients are always assembled from its mesh.
    if (const toml::node* node = s.table.get("coefficients");
        node && node->value<std::string>() == "tensor-free")
        reader.fail(
            s, "coefficients",
            "a surface's structural coefficients are always assembled (tensor-free advection "
            "runs on grid bases only); use auto, dense or sparse",
            node);
}

void checkSurfaceSimulation(const TomlReader& reader, const Section& s,
                            const SimulationSpec& simulation) {
    if (simulation.mhd)
        reader.fail(s, "mhd", "MHD is simulated in grid scenes only, not on surfaces",
                    s.table.get("mhd"));
}

void checkSurfaceInitial(const TomlReader& reader, const Section& s) {
    if (reader.string(s, "velocity") == "vortices")
        reader.fail(s, "velocity",
                    "vortices are projected on a grid; on a surface use zero, random or modes "
                    "(a solid rotation of a sphere is its first three modes)",
                    s.table.get("velocity"));
}

}  // namespace modeflow::scene
