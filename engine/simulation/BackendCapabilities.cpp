#include "engine/simulation/BackendCapabilities.h"

namespace modeflow {
namespace {

constexpr BackendCapabilities kCpuReference{"the CPU reference", "cpu", false};
constexpr BackendCapabilities kVulkan{"a Vulkan device", "vulkan", true};

}  // namespace

const BackendCapabilities& capabilitiesOf(BackendKind kind) {
    return kind == BackendKind::CpuReference ? kCpuReference : kVulkan;
}

}  // namespace modeflow
