/// Fuzz target: the scene loader on arbitrary text.

#include "precompute/scene/SceneLoader.h"
#include "tests/fuzz/FuzzSupport.h"
#include "tests/fuzz/FuzzTargets.h"

namespace modeflow::fuzz {

void sceneLoader(std::string_view bytes) {
    // Mesh paths resolve against the origin's folder, which holds no meshes: refused by name.
    acceptedOrRefused([&] { parseScene(bytes, "fuzz/scene.toml"); });
}

}  // namespace modeflow::fuzz
