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
    return acceptedOrRefused([&] { parseScene(bytes, origin); });
}

}  // namespace modeflow::fuzz
