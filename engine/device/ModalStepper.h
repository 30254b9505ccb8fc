#pragma once
/// @file ModalStepper.h
/// The reduced fluid (Euler, Navier–Stokes, LANS-α; README.md, "Reduced dynamics") advanced on the device in float32:
/// the state, the modal force and the integrator's scratch vectors live in device buffers, and a
/// step is recorded into a CommandSequence, so any number of steps (and the kernels that consume
/// the velocity) go in one submission. CPU reference: ModalIntegrator over a FluidSystem with the
/// same parameters and a force held constant over the step.
///
/// Schemes: explicit Euler, classical RK4, and the implicit midpoint rule (seed eq. 6.8) solved by
/// fixed-point iteration on the device until the midpoint state changes by at most `tolerance`
/// (relative, max norm), with no host round trip: the iteration that converges switches the
/// remaining recorded iterations off through their indirect dispatch arguments. The fixed point
/// converges when h·|∂R/∂v|/2 < 1, the same bound that keeps an explicit step accurate; a step
/// that reaches `maxIterations` keeps its state (a diverging iterate would blow up) and is counted
/// in status(), so the caller can take smaller substeps. Viscosity is applied exactly,
/// Strang-split as on the CPU. (The trapezoidal rule and MHD run on the CPU reference only.)

#include <cstdint>
#include <memory>

#include <Eigen/Core>

#include "engine/dynamics/FluidSystem.h"
#include "engine/simulation/ModalStepping.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModalKernels.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/core/SceneSpec.h"

namespace modeflow::device {

struct DeviceStepSettings {
    Integrator scheme = Integrator::Midpoint;  ///< explicit, rk4 or midpoint
    /// Midpoint: converged when max|Δ ybar| ≤ tolerance · max|ybar| between two iterations, or
    /// when the change stops halving below 16 · tolerance (float32 round-off leaves changes of a
    /// few 1e-8 that no iteration removes). Each unconverged 1e-6 would leave an energy error of
    /// that order per step; 1e-7 keeps 1000 large steps within 1e-5 (ModalStepKernelTest).
    float tolerance = 1e-7f;
    int maxIterations = 30;  ///< midpoint iterations recorded per step
};

struct DeviceStepStatus {
    int iterations = 0;        ///< midpoint iterations of the last step (0 for explicit schemes)
    double residual = 0.0;     ///< the last relative change of the midpoint state
    bool converged = true;     ///< whether the last step met the tolerance
    int unconvergedSteps = 0;  ///< steps so far that reached maxIterations
};

class ModalStepper final : public ModalStepping {
public:
    /// The decay rates νκ² and mass 1 + α²κ² come from `parameters` as in FluidSystem. The
    /// coefficients are uploaded; `coefficients` need not outlive the stepper.
    /// @throw modeflow::Error for the trapezoidal scheme, bad settings or parameters, or a
    /// device error.
    ModalStepper(const vulkan::VulkanContext& context, const StructuralCoefficients& coefficients,
                 const FluidParameters& parameters, DeviceStepSettings settings = {});

    int size() const { return mCoefficients.size(); }
    const DeviceStepSettings& settings() const { return mSettings; }
    const DeviceCoefficients& coefficients() const { return mCoefficients; }

    /// The scheme of the steps recorded from now on.
    /// @throw modeflow::Error for the trapezoidal scheme.
    void setScheme(Integrator scheme);
    /// New viscosity and LANS-α (κ² as in the constructor) for the steps recorded from now on.
    /// Between submissions only.
    /// @throw modeflow::Error for parameters FluidSystem refuses, or held modes ([forcing]).
    void setParameters(const FluidParameters& parameters);
    /// Host ↔ device copies of the state v and the force f; call between submissions.
    void setState(const Eigen::VectorXd& v) override;
    Eigen::VectorXd state() const override;
    void setForce(const Eigen::VectorXd& f);
    /// The device vectors (N floats), for kernels that read v or write f in the same submission.
    const vulkan::DeviceBuffer& stateBuffer() const { return mState; }
    const vulkan::DeviceBuffer& forceBuffer() const { return mForce; }

    /// Records one step of size h (h may be negative: the midpoint rule is then reversible) as
    /// `substeps` steps of h / substeps.
    void recordStep(vulkan::CommandSequence& sequence, double h, int substeps = 1) const;
    /// Dispatches recordStep records per substep (for sizing timed sequences).
    std::size_t dispatchesPerStep() const;
    /// The last step's convergence, read from the device after the submission.
    DeviceStepStatus status() const;
    /// One unforced step of size h in a submission of its own (`modeflow modes`): the force
    /// buffer is zeroed first. Iterations are fixed-point iterations.
    StepReport step(double h) override;

private:
    /// Held modes ([forcing]) are the CPU reference's only (BackendCapabilities).
    static void requireNoHeldModes(const FluidParameters& parameters);
    void recordUpdate(vulkan::CommandSequence& sequence, std::uint32_t op, std::uint32_t stage, double h,
                      bool indirect) const;
    void upload(vulkan::DeviceBuffer& buffer, const Eigen::VectorXd& values, const char* what) const;

    const vulkan::VulkanContext& mContext;
    DeviceStepSettings mSettings;
    /// The submission of standalone steps, made by the first step().
    std::unique_ptr<vulkan::CommandSequence> mStandalone;
    ModalKernels mKernels;
    DeviceCoefficients mCoefficients;
    std::uint32_t mApplyDispatches = 0;  ///< dispatches of one contraction
    vulkan::DeviceBuffer mState, mPoint, mWeighted, mRhs, mForce, mMass, mDecay, mAccumulator, mStatus,
        mArguments;
};

}  // namespace modeflow::device
