#include "engine/simulation/BackendCapabilities.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

constexpr BackendCapabilities kCpuReference{"the CPU reference", "cpu", true, true, true, false, true};
constexpr BackendCapabilities kVulkan{"a Vulkan device", "vulkan", false, false, false, true, false};

}  // namespace

const BackendCapabilities& capabilitiesOf(BackendKind kind) {
    return kind == BackendKind::CpuReference ? kCpuReference : kVulkan;
}

void requireSupport(const SceneSpec& scene, BackendKind kind, std::optional<Integrator> integrator,
                    std::string_view integratorOption) {
    const BackendCapabilities& backend = capabilitiesOf(kind);
    const std::string file = scene.sourceFile.empty() ? scene.name : scene.sourceFile.string();
    if (scene.isSurface() && !backend.surfaces)
        throw Error(file + ": [surface] scenes run on the CPU reference only; use --device cpu");
    if (scene.simulation.mhd && !backend.mhd)
        throw Error(file + ": [simulation].mhd runs on the CPU reference only; use --device cpu");
    if (scene.forcing.holds() && !backend.forcing)
        throw Error(file +
                    ": [forcing] (held modes) runs on the CPU reference only; use --device cpu");
    if (!backend.trapezoidal) {
        const std::string where = integrator ? std::string(integratorOption) + " trapezoidal"
                                             : file + ": [simulation].integrator = \"trapezoidal\"";
        if (integrator.value_or(scene.simulation.integrator) == Integrator::Trapezoidal)
            throw Error(where + " runs on the CPU reference only; use --device cpu, or explicit, rk4 or "
                                "midpoint on " + std::string(backend.name));
    }
}

}  // namespace modeflow
