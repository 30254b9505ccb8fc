#include "engine/device/FireBurn.h"

#include <algorithm>
#include <array>
#include <cmath>
// The generated header uses uint32_t without including <cstdint>.
#include <cstdint>
#include <string>

#include "engine/core/Error.h"
#include "engine/device/SmokeState.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/FireBurnParams.h"
#include "shaders/fire_burn.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroupSize = 128;

}  // namespace

FireBurnKernel::FireBurnKernel(const vulkan::VulkanContext& context)
    : mContext(context),
      mKernel(context, vulkan::ComputeKernelSpec{"fire_burn", fire_burn_spv, 4,
                                                 sizeof(shaders::FireBurnParams), kWorkgroupSize}) {
}

void FireBurnKernel::record(vulkan::CommandSequence& sequence, SmokeState& state,
                            const FireSpec& fire, double dt) const {
    if (!state.fire()) throw Error("fire_burn: the smoke state carries no fuel");
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw Error("fire_burn: the step " + std::to_string(dt) + " is not positive and finite");
    const std::int64_t cells = state.cellCount();
    if (cells >= (std::int64_t(1) << 32))
        throw Error("fire_burn: " + std::to_string(cells) +
                    " smoke cells, at most 2^32 - 1 supported");
    shaders::FireBurnParams params{};
    params.cellCount = std::uint32_t(cells);
    params.ignition = float(fire.ignition);
    // 1 − e^{−x} without the cancellation of a small x, as the CPU reference.
    params.burnFraction = float(-std::expm1(-fire.burnRate * dt));
    params.heat = float(fire.heat);
    params.smoke = float(fire.smoke);
    params.inverseDt = float(1.0 / dt);
    // Bindings 0-3 of shaders/fire_burn.comp.
    const std::array<const vulkan::DeviceBuffer*, 4> buffers{
        &state.fields(SmokePair::Smoke), &state.second(SmokePair::Smoke),
        &state.fields(SmokePair::Fuel), &state.second(SmokePair::Fuel)};
    const std::int64_t perDispatch =
        std::int64_t(mContext.properties().limits.maxComputeWorkGroupCount[0]) * kWorkgroupSize;
    for (std::int64_t first = 0; first < cells; first += perDispatch) {
        params.firstCell = std::uint32_t(first);
        const std::int64_t chunk = std::min(perDispatch, cells - first);
        sequence.dispatch(mKernel, buffers, params,
                          std::uint32_t((chunk + kWorkgroupSize - 1) / kWorkgroupSize));
    }
}

}  // namespace modeflow::device
