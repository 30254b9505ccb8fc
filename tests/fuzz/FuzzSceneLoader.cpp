/// Fuzz target: the scene loader on arbitrary text.

#include <filesystem>

#include "precompute/scene/SceneLoader.h"
#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {

bool sceneLoader(std::string_view bytes) {
    // The scene is read as if it stood beside a closed mesh, blob.obj, so that a mesh domain
    // (tests/fuzz/corpus/SceneLoader/every_choice.toml) gets past the loader's file check and
    // the keys after it are reached; other mesh paths are refused by name.
    static const std::filesystem::path origin =
        scratchFile("blob.obj",
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
            .parent_path() /
        "scene.toml";
    SceneSpec scene;
    if (!acceptedOrRefused([&] { scene = parseScene(bytes, origin); })) return false;
    // What the loader promises of [forcing] hold_modes: inside the basis, never all of it (a
    // scene that holds every mode would be refused only after its precompute).
    long long held = 0;
    for (const ModeRange& range : scene.forcing.holdModes) {
        require(range.first >= 1 && range.first <= range.last &&
                    range.last <= scene.basis.velocityCount(),
                "an accepted hold_modes range lies outside the basis");
        held += range.last - range.first + 1;
    }
    require(held < scene.basis.velocityCount(), "an accepted hold_modes holds every mode");
    return true;
}

}  // namespace modeflow::fuzz
