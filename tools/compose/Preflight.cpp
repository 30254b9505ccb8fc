#include "tools/compose/Preflight.h"

#include "engine/simulation/BackendCapabilities.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/compose/MemoryPreflight.h"

namespace modeflow {

Preflight preflight(const std::filesystem::path& sceneFile, std::string_view deviceOption,
                    RunParts parts) {
    Preflight checked{parseDeviceOption(deviceOption), loadScene(sceneFile), {}};
    requireSupport(checked.scene, checked.backend.kind);
    if (parts == RunParts::DynamicsAndSmoke)
        checked.memory = requireRunMemory(checked.scene, checked.backend.kind);
    return checked;
}

}  // namespace modeflow
