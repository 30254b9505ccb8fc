#pragma once
/// @file ConservativeTransport.h
/// The flux form of smoke advection on the device (`[smoke] advection = "conservative"`),
/// float32: the rules of engine/reference/ConservativeTransport.h (the CPU reference), in the
/// kernels of shaders/SmokeFlux.glsl. A step is two submissions: the first samples the velocity
/// on the smoke faces and reduces the worst Courant number (recordCourant), the host then reads
/// it and takes fluxSubsteps() of it (substeps), and the second records that many substeps of
/// every pair, the emitters added in the last (record). Why not a recorded budget with an early
/// out: the substeps of a step are known only from its velocity, and a budget too small would
/// have to be redone from a copy of the fields; one extra fence a step is cheaper.

#include <optional>

#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeAdvectionKernels;
class SmokeState;

class ConservativeTransport {
public:
    /// Buffers for `state`'s smoke faces. @throw modeflow::Error if a pipeline or a buffer
    /// cannot be made.
    ConservativeTransport(const vulkan::VulkanContext& context, const SmokeState& state);

    /// Records the face pairs of `velocity` (a float32 face field of the basis grid), the smoke
    /// faces' velocities and the step's worst Courant number over dt.
    void recordCourant(vulkan::CommandSequence& sequence, const SmokeAdvectionKernels& advection,
                       const SmokeState& state, const vulkan::DeviceBuffer& velocity,
                       double dt) const;
    /// After recordCourant's submission: the substeps the step takes.
    /// @throw modeflow::Error beyond maxFluxSubsteps (the message of fluxSubsteps).
    int substeps() const;
    /// Records `substeps` substeps of every pair of `state` over dt, the emitters' rates times dt
    /// added in the last, and leaves the state's current fields the result.
    void record(vulkan::CommandSequence& sequence, SmokeState& state, double dt,
                int substeps) const;

private:
    const vulkan::VulkanContext& mContext;
    int mDim;
    vulkan::ComputeKernel mVelocity, mCourant, mStep;
    vulkan::DeviceBuffer mFaceVelocity;  ///< one float a smoke face
    vulkan::DeviceBuffer mWorst;         ///< the float bits of the worst Courant number
};

}  // namespace modeflow::device
