#include "engine/device/ModalStepper.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/device/DofFaces.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/ModalStepParams.h"

namespace modeflow::device {
namespace {

DeviceStepSettings checked(DeviceStepSettings settings) {
    if (!(settings.tolerance > 0.0f))
        throw Error("device implicit-step tolerance must be positive");
    if (settings.maxIterations < 1)
        throw Error("device implicit-step iterations must be at least 1");
    return settings;
}

/// Floats per part of the state: N padded as the pair-sum kernel reads a vector, and for MHD's
/// second part to where a buffer view may start (DeviceBuffer::kViewAlignment).
std::uint32_t strideFor(int n, bool mhd) {
    constexpr std::size_t viewFloats = vulkan::DeviceBuffer::kViewAlignment / sizeof(float);
    return std::uint32_t(mhd ? (std::size_t(n) + viewFloats - 1) / viewFloats * viewFloats
                             : paddedSize(n));
}

vulkan::DeviceBuffer zeros(const vulkan::VulkanContext& context, std::size_t floats,
                           const char* name) {
    return vulkan::DeviceBuffer::fromValues<float>(context, std::vector<float>(floats, 0.0f), name);
}

/// The full indirect arguments (one VkDispatchIndirectCommand per dispatch of an iteration),
/// followed by the live copy the device resets and zeroes, then the same two for the linearized
/// predictor's evaluation of R(x) (modal_update.comp's BEGIN).
std::vector<std::uint32_t> indirectArguments(const std::vector<std::uint32_t>& iteration,
                                             const std::vector<std::uint32_t>& predictor) {
    std::vector<std::uint32_t> words;
    for (const auto* groups : {&iteration, &iteration, &predictor, &predictor})
        for (std::uint32_t g : *groups) words.insert(words.end(), {g, 1u, 1u});
    return words;
}

bool modelIsMhd(const DeviceModel& model) {
    return std::holds_alternative<MhdParameters>(model);
}

}  // namespace

DeviceModel modelOf(const SimulationSettings& settings) {
    if (!settings.mhd) return settings.fluid;
    return MhdParameters{settings.fluid.kappaSquared, settings.fluid.viscosity,
                         settings.magneticDiffusivity};
}

void ModalStepper::requireSchemeFits(Integrator scheme) const {
    if (scheme == Integrator::Linearized && mMhd)
        throw Error(std::string("modal step: ") + kLinearizedNeedsAFluid);
}

ModalStepper::ModalStepper(const vulkan::VulkanContext& context,
                           const StructuralCoefficients& coefficients, const DeviceModel& model,
                           DeviceStepSettings settings, const BasisCache* cache,
                           const ModeBuffer* modes)
    : mContext(context),
      mSettings(checked(settings)),
      mMhd(modelIsMhd(model)),
      mLorentz(mMhd && std::get<MhdParameters>(model).lorentzForce),
      mStride(strideFor(coefficients.size(), mMhd)),
      mParts(mMhd ? 2 : 1),
      mKernels(context),
      mCoefficients(context, coefficients, cache, modes, mMhd),
      mState(zeros(context, mParts * mStride, "modal state")),
      mPoint(zeros(context, mParts * mStride, "modal evaluation point")),
      mWeighted(zeros(context, mParts * mStride, "modal weighted point")),
      mRhs(zeros(context, (mMhd ? 3 : 1) * mStride, "modal right-hand side")),
      mForce(zeros(context, mParts * mStride, "modal force")),
      mMass(zeros(context, mParts * mStride, "modal mass")),
      // The rates, then what each part decays toward (modal_update.comp).
      mDecay(zeros(context, 2 * mParts * mStride, "modal decay rates")),
      mInverseMass(zeros(context, mParts * mStride, "modal inverse mass")),
      mAccumulator(zeros(context, mParts * mStride, "modal accumulator")),
      // Anderson's 2 ANDERSON_DEPTH + 2 vectors, the warm start's R and the linearized rule's
      // held rate (modal_update.comp).
      mHistory(
          zeros(context, (2 * ANDERSON_DEPTH + 4) * mParts * mStride, "modal iteration history")),
      mStatus(vulkan::DeviceBuffer::fromValues<shaders::ModalStatus>(
          context, std::vector<shaders::ModalStatus>(1), "modal status")),
      mArguments(context, 4, "modal indirect arguments") {
    requireSchemeFits(mSettings.scheme);
    uploadModel(model);
    if (mMhd) {
        mField.emplace(part(mState, 1, "magnetic field"));
        mPointField.emplace(part(mPoint, 1, "field evaluation point"));
        mInduction.emplace(part(mRhs, 1, "induction"));
        mLorentzForce.emplace(part(mRhs, 2, "Lorentz force"));
    }
    buildArguments();
}

void ModalStepper::buildArguments() {
    mEvaluationDispatches = std::uint32_t(evaluationGroups().size());
    std::vector<std::uint32_t> groups = iterationGroups();
    mIterationDispatches = std::uint32_t(groups.size());
    groups.push_back(1);  // modal_update
    mArguments = vulkan::DeviceBuffer::fromValues<std::uint32_t>(
        mContext, indirectArguments(groups, evaluationGroups()), "modal indirect arguments");
}

vulkan::DeviceBuffer ModalStepper::part(const vulkan::DeviceBuffer& whole, int index,
                                        const char* name) const {
    return vulkan::DeviceBuffer(whole, VkDeviceSize(index) * mStride * sizeof(float),
                                VkDeviceSize(mStride) * sizeof(float), name);
}

void ModalStepper::uploadLinear(const LinearModalTerm* linear) {
    if (!linear) {
        mLinear.reset();
        return;
    }
    const int n = size();
    if (linear->size() != n)
        throw Error("modal step: a linear term of " + std::to_string(linear->size()) +
                    " modes for a basis of " + std::to_string(n));
    const Eigen::MatrixXd& d = linear->matrix();
    if (!d.allFinite()) throw Error("modal step: the linear term is not finite");
    const std::size_t bytes = std::size_t(n) * mStride * sizeof(float);
    if (bytes > mContext.texelBufferLimit())
        throw Error("modal step: the wind's " + std::to_string(n) + " x " + std::to_string(n) +
                    " matrix of " + std::to_string(bytes) + " bytes exceeds the " +
                    std::to_string(mContext.texelBufferLimit()) + "-byte buffer limit of " +
                    mContext.deviceName() + "; use fewer modes or --device cpu");
    std::vector<float> rows(std::size_t(n) * mStride, 0.0f);  // zero-padded rows
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            rows[std::size_t(k) * mStride + std::size_t(j)] = float(d(k, j));
    mLinear.emplace(vulkan::DeviceBuffer::fromValues<float>(mContext, rows, "modal linear term"));
}

void ModalStepper::uploadModel(const DeviceModel& model) {
    if (modelIsMhd(model) != mMhd)
        throw Error(std::string("modal step: parameters of ") +
                    (modelIsMhd(model) ? "MHD" : "a fluid") + " for a stepper of " +
                    (mMhd ? "MHD" : "a fluid"));
    const int n = size();
    if (const auto* fluid = std::get_if<FluidParameters>(&model)) {
        // Checked (decayRatesOf refuses a held mode outside the basis) before anything changes.
        const Eigen::VectorXd decay = FluidSystem::decayRatesOf(*fluid, n);
        const Eigen::VectorXd mass = FluidSystem::massOf(*fluid, n);
        // Held modes ([forcing]) move at rate 0: v̇_k = 0, forces included, as FluidSystem's.
        Eigen::VectorXd inverse = mass.cwiseInverse();
        for (const int k : fluid->held) inverse[k] = 0.0;
        uploadLinear(fluid->linear.get());
        mFiltered = (mass.array() != 1.0).any();
        upload(mMass, mass, 0, "mass");
        upload(mInverseMass, inverse, 0, "inverse mass");
        upload(mDecay, decay, 0, "decay rates");
        upload(mDecay,
               fluid->viscousTarget.size() != 0 ? fluid->viscousTarget : Eigen::VectorXd::Zero(n),
               mParts, "viscous targets");
        return;
    }
    const MhdParameters& mhd = std::get<MhdParameters>(model);
    if (mhd.lorentzForce != mLorentz)
        throw Error("modal step: the Lorentz force is set when the stepper is made");
    // MhdSystem's rates, checked as FluidSystem checks its own: νκ² for v, ηκ² for F.
    const auto rates = [&](double diffusivity) {
        return FluidSystem::decayRatesOf({mhd.kappaSquared, diffusivity, 0.0}, n);
    };
    const Eigen::VectorXd velocityRates = rates(mhd.viscosity),
                          fieldRates = rates(mhd.magneticDiffusivity);
    for (int p = 0; p < 2; ++p) {
        upload(mMass, Eigen::VectorXd::Ones(n), p, "mass");
        upload(mInverseMass, Eigen::VectorXd::Ones(n), p, "inverse mass");
    }
    upload(mDecay, velocityRates, 0, "decay rates");
    upload(mDecay, fieldRates, 1, "decay rates");
}

void ModalStepper::upload(vulkan::DeviceBuffer& buffer, const Eigen::VectorXd& values, int part,
                          const char* what, VkDeviceSize offset) const {
    if (values.size() != size())
        throw Error(std::string("modal ") + what + " has " + std::to_string(values.size()) +
                    " entries, the basis " + std::to_string(size()));
    const std::vector<float> rounded(values.begin(), values.end());
    buffer.upload<float>(rounded, offset + VkDeviceSize(part) * mStride * sizeof(float));
}

Eigen::VectorXd ModalStepper::download(const vulkan::DeviceBuffer& buffer, int part,
                                       VkDeviceSize offset) const {
    std::vector<float> values(static_cast<std::size_t>(size()));
    buffer.download<float>(values, offset + VkDeviceSize(part) * mStride * sizeof(float));
    return Eigen::Map<const Eigen::VectorXf>(values.data(), size()).template cast<double>();
}

void ModalStepper::setIntegrator(Integrator scheme) {
    requireSchemeFits(scheme);
    DeviceStepSettings settings = mSettings;
    settings.scheme = scheme;
    mSettings = checked(settings);
    buildArguments();  // a linearized iteration dispatches other kernels than R's evaluation
    dropHeldRhs();     // what another scheme held is no start for this one
}

void ModalStepper::setParameters(const DeviceModel& model) {
    uploadModel(model);
    dropHeldRhs();
    buildArguments();  // the contraction's dispatches follow the mass (C(Mv, v) or C(v, v))
}

void ModalStepper::setState(const Eigen::VectorXd& x) {
    if (x.size() != dimension())
        throw Error("modal state has " + std::to_string(x.size()) + " entries, the model " +
                    std::to_string(dimension()));
    upload(mState, x.head(size()), 0, "state");
    if (mMhd) upload(mState, x.tail(size()), 1, "state");
    dropHeldRhs();
}

void ModalStepper::dropHeldRhs() {
    const std::array<std::uint32_t, 2> no{0, 0};
    static_assert(offsetof(shaders::ModalStatus, heldRate) ==
                  offsetof(shaders::ModalStatus, heldRhs) + sizeof(std::uint32_t));
    mStatus.upload<std::uint32_t>(no, offsetof(shaders::ModalStatus, heldRhs));
}

VkDeviceSize ModalStepper::heldRateOffset() const {
    return VkDeviceSize(2 * ANDERSON_DEPTH + 3) * mParts * mStride * sizeof(float);
}

VkDeviceSize ModalStepper::rhsBeforeOffset() const {
    return VkDeviceSize(2 * ANDERSON_DEPTH + 2) * mParts * mStride * sizeof(float);
}

std::vector<Eigen::VectorXd> ModalStepper::warmStart() const {
    shaders::ModalStatus raw{};
    mStatus.download<shaders::ModalStatus>(std::span(&raw, 1));
    if (raw.heldRhs == 0 || !warms()) return {};
    // The R modal_update.comp's BEGIN reads: r, less the Lorentz part with MHD (its rhs()).
    std::vector<float> r(std::size_t((mMhd ? 3 : 1) * mStride));
    mRhs.download<float>(r);
    Eigen::VectorXd newest(dimension());
    for (int p = 0; p < int(mParts); ++p)
        for (int k = 0; k < size(); ++k) {
            const std::size_t at = std::size_t(p) * mStride + std::size_t(k);
            newest[p * size() + k] = p == 0 && mLorentz ? r[at] - r[2 * mStride + k] : r[at];
        }
    std::vector<Eigen::VectorXd> rhs{newest};
    if (raw.heldRhs >= 2) {
        Eigen::VectorXd before(dimension());
        for (int p = 0; p < int(mParts); ++p)
            before.segment(p * size(), size()) = download(mHistory, p, rhsBeforeOffset());
        rhs.push_back(before);
    }
    return rhs;
}

void ModalStepper::setWarmStart(const std::vector<Eigen::VectorXd>& rhs) {
    const auto hold = [&](std::uint32_t count) {  // the held rate (its own word) stays
        mStatus.upload<std::uint32_t>(std::span(&count, 1),
                                      offsetof(shaders::ModalStatus, heldRhs));
    };
    hold(0);
    if (rhs.empty()) return;
    if (!warms())
        throw Error(
            "modal step: only the midpoint rule with its warm start holds right-hand sides "
            "between steps");
    if (rhs.size() > 2)
        throw Error("modal step: a warm start of " + std::to_string(rhs.size()) +
                    " right-hand sides (at most 2)");
    for (const Eigen::VectorXd& r : rhs) {
        if (r.size() != dimension())
            throw Error("modal step: a warm-start right-hand side of " + std::to_string(r.size()) +
                        " entries, the state " + std::to_string(dimension()));
        if (!r.allFinite()) throw Error("modal step: the warm start is not finite");
    }
    // BEGIN reads r = [v part; F part; Lorentz part] as r_v - r_Lorentz: the Lorentz part is
    // zeroed, so the difference is the value given, exactly.
    if (mLorentz) upload(mRhs, Eigen::VectorXd::Zero(size()), 2, "warm start");
    for (int p = 0; p < int(mParts); ++p) {
        upload(mRhs, rhs[0].segment(p * size(), size()), p, "warm start");
        if (rhs.size() == 2)
            upload(mHistory, rhs[1].segment(p * size(), size()), p, "warm start",
                   rhsBeforeOffset());
    }
    hold(std::uint32_t(rhs.size()));
}

Eigen::VectorXd ModalStepper::heldRate() const {
    shaders::ModalStatus raw{};
    mStatus.download<shaders::ModalStatus>(std::span(&raw, 1));
    if (raw.heldRate == 0 || mSettings.scheme != Integrator::Linearized) return {};
    std::vector<float> values(static_cast<std::size_t>(size()));
    mHistory.download<float>(values, heldRateOffset());
    return Eigen::Map<const Eigen::VectorXf>(values.data(), size()).template cast<double>();
}

void ModalStepper::setHeldRate(const Eigen::VectorXd& rate) {
    if (rate.size() == 0) {
        dropHeldRhs();
        return;
    }
    if (mSettings.scheme != Integrator::Linearized)
        throw Error("modal step: only the linearized rule holds a rate between steps");
    if (rate.size() != size())
        throw Error("modal step: a held rate of " + std::to_string(rate.size()) +
                    " entries, the basis " + std::to_string(size()));
    if (!rate.allFinite()) throw Error("modal step: the held rate is not finite");
    const std::vector<float> rounded(rate.begin(), rate.end());
    mHistory.upload<float>(rounded, heldRateOffset());
    const std::uint32_t yes = 1;
    mStatus.upload<std::uint32_t>(std::span(&yes, 1), offsetof(shaders::ModalStatus, heldRate));
}

Eigen::VectorXd ModalStepper::state() const {
    if (!mMhd) return download(mState, 0);
    Eigen::VectorXd x(dimension());
    x << download(mState, 0), download(mState, 1);
    return x;
}

void ModalStepper::setForce(const Eigen::VectorXd& f) {
    upload(mForce, f, 0, "force");
}

Eigen::VectorXd ModalStepper::velocity() const {
    return download(mState, 0);
}

void ModalStepper::setVelocity(const Eigen::VectorXd& v) {
    upload(mState, v, 0, "velocity");
    dropHeldRhs();
}

Eigen::VectorXd ModalStepper::magneticField() const {
    magneticFieldBuffer();
    return download(mState, 1);
}

void ModalStepper::setMagneticField(const Eigen::VectorXd& f) {
    magneticFieldBuffer();
    upload(mState, f, 1, "magnetic field");
    dropHeldRhs();
}

const vulkan::DeviceBuffer& ModalStepper::magneticFieldBuffer() const {
    if (!mField) throw Error("simulation: this run simulates no magnetic field ([simulation].mhd)");
    return *mField;
}

DeviceStepStatus ModalStepper::status() const {
    shaders::ModalStatus raw{};
    mStatus.download<shaders::ModalStatus>(std::span(&raw, 1));
    if (!isImplicit(mSettings.scheme)) return {0, 0.0, true, 0};
    return {int(raw.iterations), double(raw.residual), raw.converged != 0, int(raw.unconverged)};
}

std::vector<std::uint32_t> ModalStepper::linearGroups() const {
    if (!mLinear) return {};
    // A subgroup per row, as modal_combine.comp.
    return {
        groupsFor(mContext, std::uint64_t(size()), std::max(1u, 64u / mContext.subgroupSize()))};
}

void ModalStepper::recordLinear(vulkan::CommandSequence& sequence,
                                IndirectArguments indirect) const {
    if (!mLinear) return;
    const std::array<const vulkan::DeviceBuffer*, 3> buffers{&*mLinear, &mPoint, &mRhs};
    indirect.dispatch(sequence, mKernels.linear, buffers,
                      shaders::CombineParams{std::uint32_t(size()), mStride / 4, 0, 0},
                      linearGroups()[0]);
}

std::vector<std::uint32_t> ModalStepper::evaluationGroups() const {
    std::vector<std::uint32_t> groups = mCoefficients.dispatchGroups(!mFiltered);
    if (!mMhd) {
        const std::vector<std::uint32_t> linear = linearGroups();
        groups.insert(groups.end(), linear.begin(), linear.end());
        return groups;
    }
    const std::vector<std::uint32_t> apply = groups, advect = mCoefficients.advectGroups();
    if (mLorentz) groups.insert(groups.end(), apply.begin(), apply.end());
    groups.insert(groups.end(), advect.begin(), advect.end());
    return groups;
}

std::vector<std::uint32_t> ModalStepper::iterationGroups() const {
    if (mSettings.scheme != Integrator::Linearized) return evaluationGroups();
    std::vector<std::uint32_t> groups = mCoefficients.isTensorFree()
                                            ? mCoefficients.dispatchGroups(false)
                                            : mCoefficients.combineGroups();
    const std::vector<std::uint32_t> linear = linearGroups();
    groups.insert(groups.end(), linear.begin(), linear.end());
    return groups;
}

void ModalStepper::recordFrozenEvaluation(vulkan::CommandSequence& sequence,
                                          IndirectArguments indirect) const {
    // r = L(x~) y = C(a, y) with a = M x~ left in place by the iterations (modal_update.comp):
    // the pair sums of a were recorded once for the step; tensor-free coefficients contract anew.
    // The linear term's Jacobian is D itself: L(x~) y gains D y.
    std::uint32_t contraction = 0;
    if (mCoefficients.isTensorFree()) {
        mCoefficients.recordApply(sequence, mKernels, mWeighted, mPoint, mRhs, indirect);
        contraction = std::uint32_t(mCoefficients.dispatchGroups(false).size());
    } else {
        mCoefficients.recordCombine(sequence, mKernels, mPoint, mRhs, indirect);
        contraction = std::uint32_t(mCoefficients.combineGroups().size());
    }
    recordLinear(sequence, indirect.after(contraction));
}

void ModalStepper::recordEvaluation(vulkan::CommandSequence& sequence,
                                    IndirectArguments indirect) const {
    if (!mMhd) {
        // C(My, y); with a mass of 1 both are y, which the tensor-free contraction reconstructs
        // once.
        mCoefficients.recordApply(sequence, mKernels, mFiltered ? mWeighted : mPoint, mPoint, mRhs,
                                  indirect);
        recordLinear(sequence, indirect.after(
                                   std::uint32_t(mCoefficients.dispatchGroups(!mFiltered).size())));
        return;
    }
    // r = [C(v, v); advect(v, F); C(F, F)] at y = [v; F] (the mass is 1).
    const auto apply = std::uint32_t(mCoefficients.dispatchGroups(true).size());
    mCoefficients.recordApply(sequence, mKernels, mPoint, mPoint, mRhs, indirect);
    std::uint32_t d = apply;
    if (mLorentz) {
        mCoefficients.recordApply(sequence, mKernels, *mPointField, *mPointField, *mLorentzForce,
                                  indirect.after(d));
        d += apply;
    }
    mCoefficients.recordAdvect(sequence, mKernels, mPoint, *mPointField, *mInduction,
                               indirect.after(d));
}

void ModalStepper::recordUpdate(vulkan::CommandSequence& sequence, std::uint32_t op,
                                std::uint32_t stage, double h, bool indirect, bool frozen) const {
    const bool warm =
        op == MODAL_OP_BEGIN && mSettings.scheme == Integrator::Midpoint && mSettings.warmStart;
    const std::array<const vulkan::DeviceBuffer*, 12> buffers{
        &mState, &mPoint,       &mWeighted, &mRhs,       &mForce,   &mMass,
        &mDecay, &mAccumulator, &mStatus,   &mArguments, &mHistory, &mInverseMass};
    const shaders::ModalUpdateParams params{std::uint32_t(size()),
                                            stage,
                                            mIterationDispatches + 1,
                                            mEvaluationDispatches,
                                            float(h),
                                            mSettings.tolerance,
                                            mStride,
                                            mParts,
                                            mSettings.accelerated ? 1u : 0u,
                                            warm ? 1u : 0u,
                                            0u,
                                            0u,
                                            0u,
                                            0u,
                                            0u,
                                            0u};
    const vulkan::ComputeKernel& kernel = mKernels.update(op, frozen, mLorentz);
    if (indirect)
        // The update is the last dispatch of an iteration; its live entry follows the full copy.
        sequence.dispatchIndirect(
            kernel, buffers, params, mArguments,
            VkDeviceSize(2 * mIterationDispatches + 1) * sizeof(VkDispatchIndirectCommand));
    else
        sequence.dispatch(kernel, buffers, params, 1);
}

void ModalStepper::recordStep(vulkan::CommandSequence& sequence, double h, int substeps) const {
    if (substeps < 1)
        throw Error("modal step: substeps must be at least 1, got " + std::to_string(substeps));
    if (substeps > 1) {
        for (int s = 0; s < substeps; ++s) recordStep(sequence, h / substeps);
        return;
    }
    const IndirectArguments live{&mArguments, mIterationDispatches + 1};
    recordUpdate(sequence, MODAL_OP_BEGIN, 0, h, false);
    switch (mSettings.scheme) {
        case Integrator::Explicit:
            recordEvaluation(sequence, {});
            recordUpdate(sequence, MODAL_OP_EXPLICIT, 0, h, false);
            break;
        case Integrator::Rk4:
            for (std::uint32_t stage = 0; stage < 4; ++stage) {
                recordEvaluation(sequence, {});
                recordUpdate(sequence, MODAL_OP_RK4_STAGE, stage, h, false);
            }
            break;
        case Integrator::Midpoint:
            for (int m = 0; m < mSettings.maxIterations; ++m) {
                recordEvaluation(sequence, live);
                recordUpdate(sequence, MODAL_OP_MIDPOINT, 0, h, true);
            }
            recordUpdate(sequence, MODAL_OP_MIDPOINT_END, 0, h, false);
            break;
        case Integrator::Trapezoidal:
            recordEvaluation(sequence, {});  // R(x), and the explicit predictor
            recordUpdate(sequence, MODAL_OP_TRAPEZOIDAL_START, 0, h, false);
            for (int m = 0; m < mSettings.maxIterations; ++m) {
                recordEvaluation(sequence, live);
                recordUpdate(sequence, MODAL_OP_TRAPEZOIDAL, 0, h, true);
            }
            recordUpdate(sequence, MODAL_OP_TRAPEZOIDAL_END, 0, h, false);
            break;
        case Integrator::Linearized:
            // R(x) for the predictor x~, switched off by BEGIN while a rate is held.
            recordEvaluation(sequence,
                             {&mArguments, 2 * (mIterationDispatches + 1) + mEvaluationDispatches});
            recordUpdate(sequence, MODAL_OP_LINEARIZED_START, 0, h, false);
            if (!mCoefficients.isTensorFree())
                mCoefficients.recordPairSums(sequence, mKernels, mWeighted);
            for (int m = 0; m < mSettings.maxIterations; ++m) {
                recordFrozenEvaluation(sequence, live);
                recordUpdate(sequence, MODAL_OP_MIDPOINT, 0, h, true, true);
            }
            recordUpdate(sequence, MODAL_OP_LINEARIZED_END, 0, h, false);
            break;
    }
}

std::size_t ModalStepper::dispatchesPerStep() const {
    const std::size_t iteration = mEvaluationDispatches + 1;
    const std::size_t frozenIteration = mIterationDispatches + 1;
    switch (mSettings.scheme) {
        case Integrator::Explicit:
            return 1 + iteration;
        case Integrator::Rk4:
            return 1 + 4 * iteration;
        case Integrator::Midpoint:
            return 2 + std::size_t(mSettings.maxIterations) * iteration;
        case Integrator::Trapezoidal:
            return 2 + std::size_t(mSettings.maxIterations + 1) * iteration;
        case Integrator::Linearized:
            return 2 + iteration +
                   (mCoefficients.isTensorFree() ? 0 : mCoefficients.pairSumGroups().size()) +
                   std::size_t(mSettings.maxIterations) * frozenIteration;
    }
    return 0;
}

StepReport ModalStepper::step(double h) {
    if (!mStandalone) mStandalone = std::make_unique<vulkan::CommandSequence>(mContext);
    setForce(Eigen::VectorXd::Zero(size()));
    recordStep(*mStandalone, h);
    mStandalone->submitAndWait();
    const DeviceStepStatus status = this->status();
    return StepReport{status.iterations, 0, status.residual, status.converged};
}

}  // namespace modeflow::device
