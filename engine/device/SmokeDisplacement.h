#pragma once
/// @file SmokeDisplacement.h
/// Smoke pushed out of solids on the device, after each step's advection (the rule:
/// engine/simulation/SmokeDisplacement.h; CPU reference engine/reference/SmokeDisplacement.h):
/// per substep shaders/smoke_displace.comp covers the box around the solids, listing the covered
/// cells that hold smoke; pushes from those (listing the cells receiving smoke) and gathers into
/// those, both dispatched indirectly over their lists; with fire, the fuel pushed and gathered the
/// same way after the smoke. The smoke's hat buffer (MacCormack's, free once the advection is done)
/// holds what the covered cells push.

#include <array>
#include <cstdint>
#include <span>

#include "engine/device/ObstacleLattices.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeState;

class SmokeDisplacement {
public:
    /// For the smoke grid of `state`.
    /// @throw modeflow::Error if a creation call fails.
    SmokeDisplacement(const vulkan::VulkanContext& context, const SmokeState& state);

    /// Uploads the solids' poses at the substeps of [t, t + dt] and records the substeps on the
    /// state's current fields; nothing without solids. Between submissions only, and one step
    /// a submission (the poses' buffer is rewritten).
    /// @throw modeflow::Error for more than maxObstacles solids, a mesh without its level set,
    ///        or solids too fast for maxDisplacementSubsteps.
    void record(vulkan::CommandSequence& sequence, SmokeState& state,
                std::span<const MovingObstacle> solids, double t, double dt);

private:
    const vulkan::VulkanContext& mContext;
    vulkan::DeviceBuffer mPoses;           ///< obstacle records, substep by substep
    vulkan::DeviceBuffer mCover, mTarget;  ///< a stamped word per smoke cell
    /// The lists' dispatch arguments and lengths, the covered cells, the receiving cells.
    vulkan::DeviceBuffer mWork, mCovered, mReceivers;
    ObstacleLattices mLattices;
    vulkan::KernelVariants mStages;  ///< by stage and solid kinds
    std::uint32_t mStamp = 0;        ///< the last substep's
};

}  // namespace modeflow::device
