#pragma once
/// @file BackendCapabilities.h
/// The two backends a scene runs on, and what tells them apart. Both simulate every scene (grids
/// and surfaces, MHD, every integrator, every coefficient storage); they differ in precision and
/// in what they report.

#include <string_view>

namespace modeflow {

/// The CPU reference (double precision, engine/reference) or a Vulkan device (float32,
/// engine/device).
enum class BackendKind { CpuReference, Vulkan };

struct BackendCapabilities {
    std::string_view name;    ///< "the CPU reference", "a Vulkan device"
    std::string_view option;  ///< the --device value that picks it ("cpu", "vulkan")
    bool stageTimes = false;  ///< per-stage times in FrameStats
};

/// The row of the table for `kind`.
const BackendCapabilities& capabilitiesOf(BackendKind kind);

/// Both backends, in the table's order.
inline constexpr BackendKind kBackends[] = {BackendKind::CpuReference, BackendKind::Vulkan};

}  // namespace modeflow
