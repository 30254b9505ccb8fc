#pragma once
/// @file ParticleAdvection.h
/// The `[[particles]]` on the device: positions and velocities as float32 in buffers sized for the
/// whole shot's emission, each step's new particles seeded on the host (ParticleEmission.h, the
/// same points as the CPU reference) and written past the last, then one invocation per particle
/// moves it (shaders/particle_step_{2d,3d}.comp; the rule: engine/simulation/ParticleMotion.h; CPU
/// reference engine/reference/ParticleAdvection.h).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/device/ObstacleLattices.h"
#include "engine/simulation/MovingObstacle.h"
#include "engine/simulation/ParticleEmission.h"
#include "engine/simulation/Particles.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeState;

class ParticleAdvection {
public:
    /// `fluidMask`: one byte per cell of the state's smoke grid, non-zero in the fluid.
    /// @throw modeflow::Error as ParticleEmission does, or if a creation call fails.
    ParticleAdvection(const vulkan::VulkanContext& context, const SmokeState& state,
                      std::span<const std::uint8_t> fluidMask, std::vector<ParticleSetSpec> sets,
                      double shotEnd);

    /// Writes what the sets emit by t + dt and records the step from t: every particle moved in
    /// the basis velocity (the state's face pairs, which the step's smoke advection writes before
    /// this), pushed out of `solids` where they are at t + dt, kept in the domain. Between
    /// submissions only, one step a submission.
    /// @throw modeflow::Error for a mesh solid without its level set.
    void record(vulkan::CommandSequence& sequence, const SmokeState& state,
                std::span<const MovingObstacle> solids, double t, double dt);

    /// Reads them back, after the submission's fence.
    Particles particles() const;
    /// @throw modeflow::Error as ParticleEmission::restore.
    void restore(const Particles& particles);
    bool empty() const { return mEmission.sets().empty(); }

private:
    const vulkan::VulkanContext& mContext;
    std::vector<std::uint8_t> mMask;
    ParticleEmission mEmission;
    std::uint32_t mCount = 0;
    vulkan::DeviceBuffer mPositions, mVelocities;  ///< vec4 each: xyz, a position's w its set
    vulkan::DeviceBuffer mSets, mPoses;
    /// The particles near a solid after the move stage, and those of them in one
    /// (shaders/ParticleStep.glsl): the next stages' arguments and the lists' lengths, the near
    /// list, their starting points, the inside list (of near slots).
    vulkan::DeviceBuffer mWork, mNear, mStarts, mInside;
    ObstacleLattices mLattices;
    /// Of the grid's dimension, by solid kinds and stage; none without sets.
    std::optional<vulkan::KernelVariants> mKernel;
    double mSetsDt = 0.0;  ///< the step the set records are for
};

}  // namespace modeflow::device
