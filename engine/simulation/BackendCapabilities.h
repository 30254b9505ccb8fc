#pragma once
/// @file BackendCapabilities.h
/// The two backends a scene runs on, and what tells them apart. Both simulate every grid scene
/// (MHD, every integrator, every coefficient storage); they differ in precision, in what they
/// report, and in that surface scenes run on the CPU reference only.
/// Every command checks a scene against this one table before any precompute or device work, so
/// a scene a backend cannot run is refused in a second, naming the key and the backend that runs
/// it.

#include <string_view>

#include "engine/core/SceneSpec.h"

namespace modeflow {

/// The CPU reference (double precision, engine/reference) or a Vulkan device (float32,
/// engine/device).
enum class BackendKind { CpuReference, Vulkan };

struct BackendCapabilities {
    std::string_view name;    ///< "the CPU reference", "a Vulkan device"
    std::string_view option;  ///< the --device value that picks it ("cpu", "vulkan")
    bool stageTimes = false;  ///< per-stage times in FrameStats
    bool surfaces = false;    ///< surface scenes ([surface])
};

/// The row of the table for `kind`.
const BackendCapabilities& capabilitiesOf(BackendKind kind);

/// Both backends, in the table's order.
inline constexpr BackendKind kBackends[] = {BackendKind::CpuReference, BackendKind::Vulkan};

/// Refuses what `kind` does not simulate (today: a [surface] scene on the device).
/// @throw modeflow::Error naming the scene file and key, and the backend that runs it.
void requireSupport(const SceneSpec& scene, BackendKind kind);

}  // namespace modeflow
