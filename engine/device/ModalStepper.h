#pragma once
/// @file ModalStepper.h
/// The reduced dynamics (engine/README.md, "Reduced dynamics") advanced on the device in float32:
/// the fluid (Euler, Navier–Stokes, LANS-α) over v, or MHD over [v; F]. The state, the modal force
/// and the integrator's scratch vectors live in device buffers, and a step is recorded into a
/// CommandSequence, so any number of steps (and the kernels that consume the velocity) go in one
/// submission. CPU reference: ModalIntegrator over a FluidSystem or MhdSystem with the same
/// parameters and a force on v held constant over the step.
///
/// Schemes: explicit Euler, classical RK4, and the implicit midpoint (seed eq. 6.8) and
/// trapezoidal (eq. 6.9) rules solved by Anderson-accelerated fixed-point iteration on the device
/// until the iterate changes by at most `tolerance` (relative, max norm), with no host round
/// trip: the iteration that converges switches the remaining recorded iterations off through
/// their indirect dispatch arguments. The plain iteration converges when h·|∂R/∂v|/2 < 1 and
/// slowly near 1; the acceleration cuts those iterations several fold (shaders/modal_update.comp
/// has how and why); a step that reaches `maxIterations` keeps its state (a diverging
/// iterate would blow up) and is counted in status(), so the caller can take smaller substeps.
/// The linearized rule (engine/dynamics/ModalIntegrator.h) takes its predictor x~ from the rate
/// held from the step before (or, with none held, evaluates R(x): dispatches that BEGIN switches
/// off through their indirect arguments while a rate is held), records the pair sums of M x~ once,
/// and iterates its linear fixed point (the midpoint map with R(y) replaced by L(x~) y) through
/// the second half of the contraction alone: one pass over the coefficients a step where the
/// midpoint rule makes one an iteration. Tensor-free
/// coefficients have no pair sums to keep and contract C(M x~, y) in every iteration. Fluids only.
/// Viscosity (and the magnetic diffusivity) is applied exactly, Strang-split as on the CPU.
///
/// A constant linear term D v of the fluid (a wind, FluidParameters::linear) joins every
/// evaluation of R and of the frozen L(x~) y: D is formed once on the host and read as a dense
/// matrix (modal_linear.comp, one pass over N² floats an evaluation).
///
/// MHD's state is two parts of `stride` floats, v then F; its right-hand side is three
/// contractions a step evaluation: C(v, v), advect(v, F) and, with the Lorentz force, C(F, F).

#include <cstdint>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModalKernels.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/simulation/ModalStepping.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::device {

struct DeviceStepSettings {
    Integrator scheme = Integrator::Midpoint;
    /// Implicit rules: converged when max|Δy| ≤ tolerance · max|y| between two iterations, or
    /// when the change stops halving below 16 · tolerance (float32 round-off leaves changes of a
    /// few 1e-8 that no iteration removes). Each unconverged 1e-6 would leave an energy error of
    /// that order per step; 1e-7 keeps 1000 large steps within 1e-5 (ModalStepKernelTest).
    float tolerance = 1e-7f;
    int maxIterations = 30;  ///< implicit iterations recorded per step
    /// Implicit rules: Anderson acceleration  of the fixed-point iteration
    /// (shaders/modal_update.comp); off, the plain iteration (for comparisons).
    bool accelerated = true;
    /// Midpoint: start a step's iteration from R extrapolated from the last converged steps
    /// (no evaluation for the first iterate, and a closer one: shaders/modal_update.comp); off,
    /// from y = x. A state written from the host starts cold.
    bool warmStart = true;
};

struct DeviceStepStatus {
    int iterations = 0;        ///< implicit iterations of the last step (0 for explicit schemes)
    double residual = 0.0;     ///< the last relative change of the implicit iterate
    bool converged = true;     ///< whether the last step met the tolerance
    int unconvergedSteps = 0;  ///< steps so far that reached maxIterations
};

/// What a ModalStepper advances: the fluid of FluidSystem, or MHD as MhdSystem over [v; F].
using DeviceModel = std::variant<FluidParameters, MhdParameters>;

/// The model of a run's settings, as reference::ModalStepper makes it.
DeviceModel modelOf(const SimulationSettings& settings);

class ModalStepper final : public ModalStepping {
public:
    /// The mass 1 + α²κ² and decay rates νκ² (MHD: [νκ²; ηκ²]) come from `model` as in
    /// FluidSystem and MhdSystem. The coefficients are uploaded; `coefficients` need not outlive
    /// the stepper. Tensor-free coefficients need their `cache` (and take `modes`, the basis
    /// already on the device, as DeviceCoefficients says; both must outlive the stepper).
    /// @throw modeflow::Error for bad settings or parameters, or a device error.
    ModalStepper(const vulkan::VulkanContext& context, const StructuralCoefficients& coefficients,
                 const DeviceModel& model, DeviceStepSettings settings = {},
                 const BasisCache* cache = nullptr, const ModeBuffer* modes = nullptr);

    /// N, the velocity modes.
    int size() const { return mCoefficients.size(); }
    /// The state's length: N, or 2N with MHD.
    int dimension() const { return mMhd ? 2 * size() : size(); }
    bool isMhd() const { return mMhd; }
    const DeviceStepSettings& settings() const { return mSettings; }
    const DeviceCoefficients& coefficients() const { return mCoefficients; }

    /// The scheme of the steps recorded from now on.
    /// @throw modeflow::Error for bad settings.
    void setIntegrator(Integrator scheme);
    /// New parameters (of the model kind the stepper was made with) for the steps recorded from
    /// now on. Between submissions only.
    /// @throw modeflow::Error for parameters FluidSystem or MhdSystem refuses, or another kind.
    void setParameters(const DeviceModel& model);
    /// Host ↔ device copies of the state (v, or [v; F]) and the force f on v (N values); call
    /// between submissions.
    void setState(const Eigen::VectorXd& x) override;
    Eigen::VectorXd state() const override;
    void setForce(const Eigen::VectorXd& f);
    /// The velocity part of the state, and MHD's field part.
    Eigen::VectorXd velocity() const;
    void setVelocity(const Eigen::VectorXd& v);
    /// @throw modeflow::Error without MHD.
    Eigen::VectorXd magneticField() const;
    void setMagneticField(const Eigen::VectorXd& f);
    /// The linearized rule's held rate (ModalIntegrator::heldRate: empty when none is held, as
    /// after any host write of the state or parameters, or with another scheme), and its restore
    /// (empty: drop it). Between submissions.
    /// @throw modeflow::Error on a wrong size, a non-finite rate, or another scheme.
    Eigen::VectorXd heldRate() const;
    void setHeldRate(const Eigen::VectorXd& rate);
    /// The midpoint rule's warm start (DeviceStepSettings::warmStart): the right-hand sides R the
    /// last converged steps ended with, newest first (none, one or two vectors of dimension()
    /// values; none with another scheme or without the warm start), and its restore (none: start
    /// the next step cold). Between submissions; set after the state, which drops it.
    /// @throw modeflow::Error for more than two vectors, a wrong size, a non-finite value, or
    /// another scheme.
    std::vector<Eigen::VectorXd> warmStart() const;
    void setWarmStart(const std::vector<Eigen::VectorXd>& rhs);
    /// The device vectors, for kernels that read v (or F) or write f in the same submission: the
    /// state buffer begins with v (N floats, padded), the force buffer with f.
    const vulkan::DeviceBuffer& stateBuffer() const { return mState; }
    const vulkan::DeviceBuffer& forceBuffer() const { return mForce; }
    /// MHD: F (N floats, padded). @throw modeflow::Error without MHD.
    const vulkan::DeviceBuffer& magneticFieldBuffer() const;

    /// Records one step of size h (h may be negative: the implicit rules are then reversible) as
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
    /// Records r = R(y) (see the file comment), its dispatches taking their counts from
    /// `indirect`.
    void recordEvaluation(vulkan::CommandSequence& sequence, IndirectArguments indirect) const;
    /// Group counts of recordEvaluation's dispatches.
    std::vector<std::uint32_t> evaluationGroups() const;
    /// Records r = L(x~) y, the right-hand side frozen at the predictor (the linearized rule).
    void recordFrozenEvaluation(vulkan::CommandSequence& sequence,
                                IndirectArguments indirect) const;
    /// Group counts of an implicit iteration's contraction: recordEvaluation's, or for the
    /// linearized rule recordFrozenEvaluation's.
    std::vector<std::uint32_t> iterationGroups() const;
    /// rhs += D y (y the evaluation point), when the fluid has a linear term.
    void recordLinear(vulkan::CommandSequence& sequence, IndirectArguments indirect) const;
    /// Group counts of recordLinear's dispatch (none without a linear term).
    std::vector<std::uint32_t> linearGroups() const;
    /// `frozen`: a linearized iteration, which leaves the weighted point (M x~) alone.
    void recordUpdate(vulkan::CommandSequence& sequence, std::uint32_t op, std::uint32_t stage,
                      double h, bool indirect, bool frozen = false) const;
    /// @throw modeflow::Error for the linearized rule with MHD.
    void requireSchemeFits(Integrator scheme) const;
    /// Uploads `values` to part `part` of a state-shaped buffer (one that begins `offset` bytes
    /// into `buffer`).
    void upload(vulkan::DeviceBuffer& buffer, const Eigen::VectorXd& values, int part,
                const char* what, VkDeviceSize offset = 0) const;
    Eigen::VectorXd download(const vulkan::DeviceBuffer& buffer, int part,
                             VkDeviceSize offset = 0) const;
    /// Mass and decay rates of `model` as state-shaped float vectors.
    void uploadModel(const DeviceModel& model);
    /// The fluid's linear term as mLinear (none: dropped).
    /// @throw modeflow::Error for a term of another size, a non-finite one, or one larger than
    ///        a texel buffer may be.
    void uploadLinear(const LinearModalTerm* linear);
    /// The indirect arguments of an implicit iteration (its dispatches' group counts, twice).
    void buildArguments();
    /// The state, the mass in R or the scheme was changed from the host: the next step starts
    /// cold (the R or rate held is not one near the new state).
    void dropHeldRhs();
    /// Where the held rate, and the warm start's R before the last, lie in mHistory.
    VkDeviceSize heldRateOffset() const;
    VkDeviceSize rhsBeforeOffset() const;
    /// Whether the steps recorded start from a warm start.
    bool warms() const { return mSettings.scheme == Integrator::Midpoint && mSettings.warmStart; }
    /// A part of `whole`, as the contractions bind it.
    vulkan::DeviceBuffer part(const vulkan::DeviceBuffer& whole, int index, const char* name) const;

    const vulkan::VulkanContext& mContext;
    DeviceStepSettings mSettings;
    bool mMhd = false;
    bool mLorentz = false;
    bool mFiltered = false;     ///< a fluid whose mass is not 1 (LANS-α): C(Mv, v), else C(v, v)
    std::uint32_t mStride = 0;  ///< floats per part of the state
    std::uint32_t mParts = 1;
    /// The submission of standalone steps, made by the first step().
    std::unique_ptr<vulkan::CommandSequence> mStandalone;
    ModalKernels mKernels;
    DeviceCoefficients mCoefficients;
    std::uint32_t mEvaluationDispatches = 0;  ///< dispatches of one evaluation of R
    std::uint32_t mIterationDispatches = 0;   ///< contraction dispatches of an implicit iteration
    vulkan::DeviceBuffer mState, mPoint, mWeighted, mRhs, mForce, mMass, mDecay, mInverseMass,
        mAccumulator, mHistory, mStatus, mArguments;
    /// The fluid's linear term D (FluidParameters::linear): N rows of `mStride` floats, read as
    /// texels; none without one.
    std::optional<vulkan::DeviceBuffer> mLinear;
    /// MHD: the field parts of the state and point, and the induction and Lorentz parts of r.
    std::optional<vulkan::DeviceBuffer> mField, mPointField, mInduction, mLorentzForce;
};

}  // namespace modeflow::device
