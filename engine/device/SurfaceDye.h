#pragma once
/// @file SurfaceDye.h
/// The dye on a surface advanced on the device, in float32 (CPU reference:
/// engine/surface/SurfaceDye.h): the advection operator K = A((v0 + v1)/2) at the step's mean
/// velocity (shaders/surface_dye_pairs.comp, one pass over the N columns of A), then the Cayley
/// step (I + h/2 K) f' = (I − h/2 K) f + h s solved in one workgroup by conjugate gradients on
/// its normal equations (shaders/surface_dye_step.comp has why they converge for any step).
/// The state [mean, f_1, …, f_M] stays on the device between steps.

#include <optional>
#include <span>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/simulation/SurfaceSources.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

struct SurfaceDyeStatus {
    int iterations = 0;     ///< conjugate-gradient iterations of the last step
    bool converged = true;  ///< whether they met the tolerance
    double residual = 0.0;  ///< the relative residual they reached
};

class SurfaceDye {
public:
    /// Uploads the basis's advection coefficients; the dye starts at zero.
    /// @throw modeflow::Error when the cache is not a surface basis, for a [[source]] that covers
    ///        no vertex (SurfaceSources), or for more scalar modes than the device's limits hold.
    SurfaceDye(const vulkan::VulkanContext& context, const BasisCache& cache,
               std::span<const SmokeEmitter> emitters);

    /// The sources' rate of the next step, from time t (written at once: between submissions).
    void setRate(double t);
    /// Records one step of h, the velocity going from `before` to `after` (the modal stepper's
    /// vectors: N floats each), with the rate set last: a recording that serves every step.
    void recordStep(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& before,
                    const vulkan::DeviceBuffer& after, double h) const;

    /// [mean, f_1, …, f_M], between submissions. @throw modeflow::Error on a wrong size.
    Eigen::VectorXd state() const;
    void setState(const Eigen::VectorXd& state);
    /// The last step's solve, read after its submission.
    SurfaceDyeStatus status() const;

private:
    int mScalars;
    int mModes;
    SurfaceSources mSources;
    vulkan::ComputeKernel mPairsKernel, mStepKernel;
    /// A's rows (one per scalar pair, N floats each); absent with fewer than two scalar modes.
    std::optional<vulkan::DeviceBuffer> mAdvection;
    vulkan::DeviceBuffer mPairs, mState, mRate, mWork, mStatus;
};

}  // namespace modeflow::device
