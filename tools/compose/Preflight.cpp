#include "tools/compose/Preflight.h"

#include <utility>

#include "precompute/scene/SceneLoader.h"
#include "tools/compose/MemoryPreflight.h"

namespace modeflow {
namespace {

Preflight checkedRun(SceneSpec scene, BackendChoice backend, RunParts parts) {
    Preflight checked{std::move(backend), std::move(scene), {}};
    if (parts == RunParts::DynamicsAndSmoke)
        checked.memory = requireRunMemory(checked.scene, checked.backend.kind);
    return checked;
}

}  // namespace

Preflight preflight(const std::filesystem::path& sceneFile, std::string_view deviceOption,
                    RunParts parts) {
    // The device option is refused before the scene file is read.
    BackendChoice backend = parseDeviceOption(deviceOption);
    return checkedRun(loadScene(sceneFile), std::move(backend), parts);
}

Preflight preflight(SceneSpec scene, std::string_view deviceOption, RunParts parts) {
    return checkedRun(std::move(scene), parseDeviceOption(deviceOption), parts);
}

}  // namespace modeflow
