#pragma once
/// @file FireBurn.h
/// Fuel burning on the device (shaders/fire_burn.comp), the step's last smoke stage with fire:
/// the rule of engine/simulation/Combustion.h (the CPU reference), over every smoke cell of a
/// SmokeState that carries fuel, in float32 with the burnt fraction 1 − e^{−r dt} from the host.

#include "engine/core/SceneSpec.h"
#include "engine/vulkan/ComputeKernel.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeState;

class FireBurnKernel {
public:
    /// @throw modeflow::Error if the pipeline cannot be created.
    explicit FireBurnKernel(const vulkan::VulkanContext& context);

    /// Records the burn of `state`'s current fields over dt by `fire`'s rule.
    /// @throw modeflow::Error when the state carries no fuel, dt is not positive and finite, or
    /// the smoke grid has 2^32 cells or more.
    void record(vulkan::CommandSequence& sequence, SmokeState& state, const FireSpec& fire,
                double dt) const;

private:
    const vulkan::VulkanContext& mContext;
    vulkan::ComputeKernel mKernel;
};

}  // namespace modeflow::device
