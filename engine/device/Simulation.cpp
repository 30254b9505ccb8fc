#include "engine/device/Simulation.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/simulation/FluxSubsteps.h"
#include "engine/simulation/SmokeDisplacement.h"
#include "engine/simulation/WindTransport.h"

namespace modeflow::device {
namespace {

/// What the device cannot run, checked before any upload.
SimulationSettings supported(SimulationSettings settings) {
    if (settings.mhd && settings.fluid.alpha > 0.0)
        throw Error("simulation: LANS-alpha and MHD cannot be combined");
    return settings;
}

/// Dispatches one step may record, for the timestamp pool: the midpoint iterations dominate.
std::uint32_t maxDispatchesPerStep(const ModalStepper& stepper, const SmokeState& smoke,
                                   AdvectionScheme advection) {
    // The displacement a substep: a fill, the cover over a box (or a box a solid) of at most
    // every smoke cell in dispatches of at least 65535 groups of 64 (the least
    // maxComputeWorkGroupCount), then four dispatches; two fills when its stamps wrap.
    const std::int64_t boxDispatches = (smoke.cellCount() + 65535 * 64 - 1) / (65535 * 64);
    // The particles: a dispatch per 65535 groups of 64.
    const std::int64_t particleDispatches = (maxParticles + 65535 * 64 - 1) / (65535 * 64);
    // The fuel's push and gather a substep, and the burn a dispatch per 65535 groups of 128.
    const std::int64_t burnDispatches = (smoke.cellCount() + 65535 * 128 - 1) / (65535 * 128);
    // The conservative smoke's substeps, a dispatch a pair each (its second submission).
    const std::int64_t fluxDispatches =
        advection == AdvectionScheme::Conservative ? 2 * std::int64_t(maxFluxSubsteps) : 0;
    return std::uint32_t(SubstepSchedule::kMaxSubsteps * stepper.dispatchesPerStep() + 64 +
                         (boxDispatches * maxObstacles + 7) * maxDisplacementSubsteps + 2 +
                         particleDispatches + burnDispatches + fluxDispatches);
}

std::vector<double> widened(const std::vector<float>& values) {
    return {values.begin(), values.end()};
}

}  // namespace

Simulation::Simulation(const vulkan::VulkanContext& context, const BasisCache& cache,
                       const StructuralCoefficients& coefficients, SimulationSettings settings,
                       std::span<const std::uint8_t> smokeMask, bool timestamps,
                       StepRecording recording)
    : mSettings(supported(withWindTransport(std::move(settings), cache))),
      mModes(cache.velocity.source == BasisSource::ClosedForm
                 ? nullptr
                 : std::make_unique<ModeBuffer>(context, cache.velocity.modes,
                                                mSettings.basisPrecision)),
      mSeparable(cache.velocity.source == BasisSource::ClosedForm
                     ? std::make_unique<SeparableTransformKernels>(context, cache)
                     : nullptr),
      mStepper(
          context, coefficients, modelOf(mSettings), DeviceStepSettings{mSettings.integrator},
          &cache,
          mModes && mSettings.basisPrecision == ModePrecision::Float32 ? mModes.get() : nullptr),
      mReconstruction(context, cache),
      mFaceVelocity(mReconstruction.makeFaceField("grid velocity")),
      mForceField(context, cache, mSettings.smokeScale),
      mProjection(context, cache, FaceQuantity::Density),
      mForceDensity(context, std::max<std::size_t>(cache.faces.size(), 1) * sizeof(float),
                    "force density"),
      mObstacles(context, cache),
      mSmoke(context, MacGrid::fromSpec(cache.grid), mSettings.smokeScale, smokeMask,
             mSettings.fire.has_value()),
      mAdvection(context),
      mDisplacement(context, mSmoke),
      mParticles(context, mSmoke, smokeMask, mSettings.particles, mSettings.shotEnd),
      mSequence(context, timestamps, maxDispatchesPerStep(mStepper, mSmoke, mSettings.advection)),
      mStepRecording(recording) {
    for (std::unique_ptr<KeptStep>& kept : mKept)
        kept = std::make_unique<KeptStep>(
            context, timestamps, maxDispatchesPerStep(mStepper, mSmoke, mSettings.advection));
    if (!(mSettings.dt > 0.0)) throw Error("simulation: dt must be positive");
    if (mSettings.stepsPerFrame < 1) throw Error("simulation: steps per frame must be at least 1");
    requireDisplaceableMotion(mSettings.obstacles, mSettings.dt, mSmoke.smokeGrid());
    if (mSettings.fire) mBurn.emplace(context);
    if (mSettings.advection == AdvectionScheme::Conservative) mFlux.emplace(context, mSmoke);
    if (mSettings.wind) {
        mWind.emplace(context, mReconstruction.grid(), windBaseFlow(cache, *mSettings.wind));
        mSmoke.setWind(*mSettings.wind);
        // The air before the first step: the wind alone, as on the CPU.
        mWind->record(mSequence, mFaceVelocity);
        mSequence.submitAndWait();
    }
    requireInflowsMeetFluid(mSmoke.outsideAir(), mSettings.inflows, smokeMask);
}

void Simulation::restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) {
    mStepper.setVelocity(v);
    if (smoke.fuel.empty() == mSmoke.fire())
        throw Error(mSmoke.fire() ? "simulation: the saved smoke carries no fuel and flame; the "
                                    "run burns fuel ([fire])"
                                  : "simulation: the saved smoke carries fuel; the run has no "
                                    "[fire]");
    const auto narrowed = [](const std::vector<double>& values) {
        return std::vector<float>(values.begin(), values.end());
    };
    mSmoke.upload(narrowed(smoke.density), narrowed(smoke.temperature));
    if (mSmoke.fire()) mSmoke.upload(narrowed(smoke.fuel), narrowed(smoke.flame), SmokePair::Fuel);
    mParticles.restore({});
    dropKeptSteps();
    mTime = time;
    mStep = std::lround(time / mSettings.dt);
    mSchedule.reset();
}

StepCarry Simulation::carry() const {
    return carryOf(mStepper, mSchedule);
}

void Simulation::setCarry(const StepCarry& carry) {
    restoreCarry(carry, mStepper, mSchedule);
}

void Simulation::setSplats(std::span<const ForceSplat> splats) {
    dropKeptSteps();  // the force stage records the splats' count
    mForceField.setSplats(splats);
    // Without forces the step reads the force buffer as it is: make it zero.
    if (!forcesActive()) mStepper.setForce(Eigen::VectorXd::Zero(mStepper.size()));
}

void Simulation::setObstacles(std::vector<MovingObstacle> obstacles) {
    if (obstacles.size() > std::size_t(maxObstacles))
        throw Error("simulation: " + std::to_string(obstacles.size()) + " obstacles, at most " +
                    std::to_string(maxObstacles) + " move at once");
    requireDisplaceableMotion(obstacles, mSettings.dt, mSmoke.smokeGrid());
    dropKeptSteps();
    mSettings.obstacles = std::move(obstacles);
}

void Simulation::setEmitters(std::vector<SmokeEmitter> emitters) {
    requireEmitterCount(emitters);
    dropKeptSteps();
    mSettings.emitters = std::move(emitters);
    // A list no step can match: the next one uploads the new emitters.
    mActiveEmitters.assign(mSettings.emitters.size() + 1, false);
}

void Simulation::setViscosity(double viscosity) {
    FluidParameters fluid = mSettings.fluid;
    fluid.viscosity = viscosity;
    SimulationSettings settings = mSettings;
    settings.fluid = fluid;
    mStepper.setParameters(modelOf(settings));
    dropKeptSteps();
    mSettings.fluid = std::move(fluid);
}

void Simulation::setIntegrator(Integrator integrator) {
    mStepper.setIntegrator(integrator);
    dropKeptSteps();
    mSettings.integrator = integrator;
}

void Simulation::setTiming(bool on) {
    // A kept step writes timestamps or not as it was recorded.
    if (on != mSequence.isTiming()) dropKeptSteps();
    mSequence.setTiming(on);
    for (const std::unique_ptr<KeptStep>& kept : mKept) kept->sequence.setTiming(on);
}

bool Simulation::prepareStep() {
    // Emitters switch on and off at step boundaries; the device list changes only when they do,
    // or when an active one moves. Their rates are uploaded in place, where kept steps read them.
    std::vector<bool> active(mSettings.emitters.size());
    bool moving = false;
    for (std::size_t e = 0; e < active.size(); ++e) {
        active[e] = mSettings.emitters[e].activeAt(mTime);
        moving = moving || (active[e] && mSettings.emitters[e].moves());
    }
    if (active != mActiveEmitters || moving) {
        mSmoke.setEmitters(activeEmitters(mSettings.emitters, mTime));
        mActiveEmitters = std::move(active);
    }
    // The ghosts too; the sides letting air in are in the step's shape.
    if (mActiveInflows.changes(mSettings.inflows, mTime))
        mSmoke.setInflows(activeInflows(mSettings.inflows, mTime));
    // Obstacles and jets where they are at the end of the step, which the advection then sees.
    mRegions = mSettings.velocityRegions(mTime);
    if (!mRegions.empty()) mObstacles.setObstacles(mRegions, mTime + mSettings.dt);
    // Solids and particles record where they are and how many there are, and conservative
    // smoke its substeps read mid-step: those steps are recorded afresh.
    return !mFlux && mSettings.obstacles.empty() && mParticles.empty();
}

Simulation::StepShape Simulation::stepShape() const {
    StepShape shape;
    shape.substeps = mSchedule.substeps();
    shape.inflowBits = mSmoke.inflowBits();
    shape.regionCount = std::uint32_t(mRegions.size());
    if (!mRegions.empty()) {
        shape.regionKinds = mObstacles.kinds();
        shape.latticeGeneration = mObstacles.latticeGeneration();
        shape.regionBox = mObstacles.cellBox();
    }
    return shape;
}

bool Simulation::recordedFor(const StepShape& kept, const StepShape& shape) const {
    return kept.substeps == shape.substeps && kept.inflowBits == shape.inflowBits &&
           kept.regionCount == shape.regionCount && kept.regionKinds == shape.regionKinds &&
           kept.latticeGeneration == shape.latticeGeneration &&
           boxContains(kept.regionBox, shape.regionBox, mObstacles.grid());
}

void Simulation::dropKeptSteps() {
    for (const std::unique_ptr<KeptStep>& kept : mKept) kept->sequence.dropKeptRecording();
}

void Simulation::recordStep(std::vector<std::size_t>& boundaries) {
    const double dt = mSettings.dt;
    boundaries.push_back(dispatchMark());
    if (forcesActive()) {
        // Without solid smoke cells the mask leaves every weight as it is: skip its loads.
        const bool solidCells = std::int64_t(mSmoke.fluidCellCount()) < mSmoke.cellCount();
        // Buoyancy alone acts on the up faces only: the other components' passes would
        // transform zeros, so they are not recorded and those DOFs of g not written.
        const bool upOnly = mSeparable && mForceField.splatCount() == 0;
        mForceField.record(recording(), mSettings.buoyancy, mSmoke.temperature(),
                           solidCells ? &mSmoke.mask() : nullptr, mForceDensity, upOnly);
        if (upOnly)
            mSeparable->recordComponentProjection(
                recording(), mForceDensity, upAxis(mReconstruction.grid()), mStepper.forceBuffer());
        else if (mSeparable)
            mSeparable->recordProjection(recording(), mForceDensity, mStepper.forceBuffer());
        else
            mProjection.record(recording(), *mModes, mForceDensity, mStepper.forceBuffer());
    }
    boundaries.push_back(dispatchMark());
    mStepper.recordStep(recording(), dt, mSchedule.substeps());
    boundaries.push_back(dispatchMark());
    if (!mRegions.empty()) {
        // The mismatch reads the velocity on the box it walks alone (a closed-form basis
        // reconstructs only that); the corrected velocity is the step's reconstruction.
        const CellBox box = mObstacles.recordBox();
        recordReconstruction(&box);
        if (mSeparable)
            mObstacles.record(recording(), *mSeparable, mFaceVelocity, mStepper.stateBuffer());
        else
            mObstacles.record(recording(), *mModes, mFaceVelocity, mStepper.stateBuffer());
    }
    boundaries.push_back(dispatchMark());
    recordReconstruction();
    boundaries.push_back(dispatchMark());
    if (mFlux) {
        // The substeps come from the step's velocity: read them between two submissions.
        mFlux->recordCourant(recording(), mAdvection, mSmoke, mFaceVelocity, dt);
        submitWithinStep();
        mFlux->record(recording(), mSmoke, dt, mFlux->substeps());
    } else {
        mAdvection.record(recording(), mSmoke, mFaceVelocity, dt, mSettings.advection);
    }
    boundaries.push_back(dispatchMark());
    mDisplacement.record(recording(), mSmoke, mSettings.obstacles, mTime, dt);
    boundaries.push_back(dispatchMark());
    if (mBurn) mBurn->record(recording(), mSmoke, *mSettings.fire, dt);
    boundaries.push_back(dispatchMark());
    mParticles.record(recording(), mSmoke, mSettings.obstacles, mTime, dt);
    boundaries.push_back(dispatchMark());
}

std::size_t Simulation::dispatchMark() const {
    return mStepDispatches + recording().dispatchCount();
}

void Simulation::submitWithinStep() {
    const std::size_t recorded = recording().dispatchCount();
    recording().submitAndWait();
    const std::vector<double>& times = recording().dispatchTimesMs();
    mStepTimesMs.insert(mStepTimesMs.end(), times.begin(), times.end());
    const std::vector<std::string>& labels = recording().dispatchLabels();
    mStepLabels.insert(mStepLabels.end(), labels.begin(), labels.end());
    mStepDispatches += recorded;
}

void Simulation::recordReconstruction(const CellBox* needed) {
    recordReconstruction(mStepper.stateBuffer(), mFaceVelocity, needed);
    if (mWind) mWind->record(recording(), mFaceVelocity);
}

void Simulation::recordReconstruction(const vulkan::DeviceBuffer& modal,
                                      const vulkan::DeviceBuffer& field,
                                      const CellBox* needed) const {
    if (mSeparable)
        mSeparable->recordReconstruction(recording(), modal, field, needed);
    else
        mReconstruction.record(recording(), *mModes, modal, field);
}

FrameStats Simulation::advanceSteps(int steps) {
    FrameStats stats;
    for (int s = 0; s < steps; ++s) {
        std::vector<std::size_t> boundaries;
        mStepDispatches = 0;
        mStepTimesMs.clear();
        mStepLabels.clear();
        const bool keepable = prepareStep();
        const StepShape shape = stepShape();
        // The advection writes the other fields of each pair each step: a kept step per parity.
        KeptStep& kept = *mKept[std::size_t(mSmoke.parity())];
        if (keepable && kept.sequence.hasKeptRecording() && recordedFor(kept.shape, shape)) {
            kept.sequence.resubmit();
            ++stats.resubmittedSteps;
            mStepTimesMs = kept.sequence.dispatchTimesMs();
            mStepLabels = kept.sequence.dispatchLabels();
            boundaries = kept.boundaries;
            if (mSmoke.parity() != kept.endParity) mSmoke.flip();
        } else {
            const bool keep = keepable && mStepRecording == StepRecording::Once;
            if (keep) {
                kept.sequence.keepNextRecording();
                // The regions' faces over the next steps, so that it serves them too.
                if (!mRegions.empty())
                    mObstacles.widenRecordBox(sweptDisplacementBox(mRegions, mTime + mSettings.dt,
                                                                   mSettings.dt, kSweptSteps,
                                                                   mObstacles.grid()));
            }
            // Back to the afresh sequence however the recording ends.
            struct Restore {
                vulkan::CommandSequence*& into;
                vulkan::CommandSequence* afresh;
                ~Restore() { into = afresh; }
            } const restore{mRecordingInto, &mSequence};
            mRecordingInto = keep ? &kept.sequence : &mSequence;
            recordStep(boundaries);
            submitWithinStep();
            if (keep) {
                kept.boundaries = boundaries;
                kept.shape = shape;
                if (!mRegions.empty()) kept.shape.regionBox = mObstacles.recordBox();
                kept.endParity = mSmoke.parity();
            }
        }
        mTime += mSettings.dt;
        ++stats.steps;
        // N floats: as cheap as the status read below (measured in engine/README.md).
        requireFiniteModalState(mStepper.state(), ++mStep, mTime);

        const DeviceStepStatus status = mStepper.status();
        stats.maxIterations = std::max(stats.maxIterations, status.iterations);
        stats.unconvergedSteps += mSchedule.advance(status);
        stats.substeps = std::max(stats.substeps, mSchedule.substeps());
        const std::vector<double>& times = mStepTimesMs;
        if (times.empty()) continue;
        ++stats.timedSteps;
        // The velocity the mismatch reads and the smoke pushed out of solids count to the
        // obstacles, the burn to the advection.
        const std::array<double*, 8> stages{
            &stats.forcesMs,    &stats.modalMs,     &stats.obstaclesMs, &stats.reconstructionMs,
            &stats.advectionMs, &stats.obstaclesMs, &stats.advectionMs, &stats.particlesMs};
        for (std::size_t stage = 0; stage < stages.size(); ++stage)
            for (std::size_t d = boundaries[stage]; d < boundaries[stage + 1]; ++d)
                *stages[stage] += times[d];
        for (std::size_t d = 0; d < times.size(); ++d) stats.kernelMs[mStepLabels[d]] += times[d];
    }
    return stats;
}

Eigen::VectorXd Simulation::magneticField() const {
    return mSettings.mhd ? mStepper.magneticField() : Eigen::VectorXd();
}

std::vector<double> Simulation::faceMagneticField() const {
    if (!mSettings.mhd) return {};
    const vulkan::DeviceBuffer field = mReconstruction.makeFaceField("magnetic face field");
    recordReconstruction(mStepper.magneticFieldBuffer(), field);
    mSequence.submitAndWait();
    std::vector<float> faces(std::size_t(mReconstruction.grid().faceTotal()));
    field.download<float>(faces);
    return widened(faces);
}

SmokeFields Simulation::smoke() const {
    std::vector<float> first(std::size_t(mSmoke.cellCount())), second(first.size());
    mSmoke.download(first, second);
    SmokeFields fields{widened(first), widened(second)};
    if (mSmoke.fire()) {
        mSmoke.download(first, second, SmokePair::Fuel);
        fields.fuel = widened(first);
        fields.flame = widened(second);
    }
    return fields;
}

std::vector<double> Simulation::faceVelocity() const {
    std::vector<float> faces(std::size_t(mReconstruction.grid().faceTotal()));
    mFaceVelocity.download<float>(faces);
    return widened(faces);
}

}  // namespace modeflow::device
