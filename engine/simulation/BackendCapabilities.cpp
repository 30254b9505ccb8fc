#include "engine/simulation/BackendCapabilities.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

constexpr BackendCapabilities kCpuReference{"the CPU reference", "cpu", false, true};
constexpr BackendCapabilities kVulkan{"a Vulkan device", "vulkan", true, false};

}  // namespace

const BackendCapabilities& capabilitiesOf(BackendKind kind) {
    return kind == BackendKind::CpuReference ? kCpuReference : kVulkan;
}

void requireSupport(const SceneSpec& scene, BackendKind kind) {
    const std::string file = scene.sourceFile.empty() ? scene.name : scene.sourceFile.string();
    if (scene.isSurface() && !capabilitiesOf(kind).surfaces)
        throw Error(file + ": [surface] scenes run on the CPU reference only; use --device cpu");
}

}  // namespace modeflow
