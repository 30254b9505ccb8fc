#pragma once
/// @file BackendCapabilities.h
/// The two backends a scene runs on, and what each of them simulates. Every command checks a
/// scene against this one table before any precompute or device work, so a scene a backend
/// cannot run is refused in a second, naming the key and the backend that runs it.

#include <optional>
#include <string_view>

#include "engine/core/SceneSpec.h"

namespace modeflow {

/// The CPU reference (double precision, engine/reference) or a Vulkan device (float32,
/// engine/device).
enum class BackendKind { CpuReference, Vulkan };

struct BackendCapabilities {
    std::string_view name;    ///< "the CPU reference", "a Vulkan device"
    std::string_view option;  ///< the --device value that picks it ("cpu", "vulkan")
    bool mhd = false;         ///< [simulation].mhd
    bool trapezoidal = false;  ///< [simulation].integrator = "trapezoidal"
    bool forcing = false;      ///< [forcing]: held modes
    bool stageTimes = false;  ///< per-stage times in FrameStats
    bool surfaces = false;    ///< surface scenes ([surface])
};

/// The row of the table for `kind`.
const BackendCapabilities& capabilitiesOf(BackendKind kind);

/// Refuses what `kind` does not simulate: the scene's [simulation] choices, or the integrator a
/// command-line option puts in their place (`integratorOption`, e.g. "--integrator").
/// @throw modeflow::Error naming the scene file and key (or the option), and the backend that
///        runs it.
void requireSupport(const SceneSpec& scene, BackendKind kind,
                    std::optional<Integrator> integrator = std::nullopt,
                    std::string_view integratorOption = "--integrator");

}  // namespace modeflow
