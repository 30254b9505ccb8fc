#pragma once
/// @file DisplayedFields.h
/// The fields the stir window draws, for any Simulator, as buffers on the display's device
/// (display::FieldBuffers). A simulation on that device is drawn from its own buffers, with
/// nothing copied; any other (the CPU reference) has its smoke, and its face velocity when the
/// picture shows arrows, uploaded each frame into display-side buffers of the same layouts.

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/display/DisplayKernels.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow {
struct RunInputs;
class Simulator;
}  // namespace modeflow

namespace modeflow::stir {

class DisplayedFields {
public:
    /// For simulations of `run` (its basis grid, smoke scale and smoke mask) drawn on
    /// `context`, the device that Backend(kind, context) simulates on for BackendKind::Vulkan;
    /// `context` must outlive this.
    /// @throw modeflow::Error when the run's smoke mask does not fit its smoke grid.
    DisplayedFields(const vulkan::VulkanContext& context, const RunInputs& run);

    /// `simulation`'s fields now, on the display's device; the face velocity is current only
    /// `withVelocity` (from the CPU it costs an upload). Valid until the next call.
    /// @throw modeflow::Error when the simulation's grids are not the run's.
    display::FieldBuffers of(const Simulator& simulation, bool withVelocity);

private:
    /// The display-side buffers, made for the first simulation that needs them.
    struct Uploaded {
        vulkan::DeviceBuffer smoke, mask, faceVelocity, flame;
    };
    Uploaded& uploaded();

    const vulkan::VulkanContext& mContext;
    MacGrid mBasisGrid, mSmokeGrid;
    std::vector<std::uint8_t> mMask;  ///< 0 or 1 per smoke cell, padded to whole words
    std::optional<Uploaded> mUploaded;
};

}  // namespace modeflow::stir
