#include "engine/simulation/ReferenceSimulation.h"

#include <algorithm>
#include <cmath>

#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/field/ForceProjection.h"
#include "engine/field/VelocityReconstruction.h"
#include "engine/format/Error.h"

namespace modeflow {
namespace {

std::unique_ptr<ModalSystem> modalSystem(const StructuralCoefficients& coefficients,
                                         const SimulationSettings& settings) {
    if (!settings.mhd) return std::make_unique<FluidSystem>(coefficients, settings.fluid);
    if (settings.fluid.alpha > 0.0)
        throw Error("simulation: LANS-alpha and MHD cannot be combined");
    return std::make_unique<MhdSystem>(
        coefficients, MhdParameters{settings.fluid.kappaSquared, settings.fluid.viscosity,
                                    settings.magneticDiffusivity});
}

std::string sizeMismatch(const char* what, Eigen::Index given, int modes) {
    return std::string("simulation: ") + what + " of " + std::to_string(given) +
           " modes, the basis has " + std::to_string(modes);
}

}  // namespace

ReferenceSimulation::ReferenceSimulation(const BasisCache& cache,
                                         const StructuralCoefficients& coefficients,
                                         SimulationSettings settings,
                                         std::vector<std::uint8_t> smokeMask)
    : mCache(cache),
      mSettings(std::move(settings)),
      mModes(coefficients.size()),
      mSystem(modalSystem(coefficients, mSettings)),
      mIntegrator(*mSystem, IntegratorSettings{mSettings.integrator}),
      mAdvection(MacGrid::fromSpec(cache.grid), mSettings.smokeScale, std::move(smokeMask)),
      mState(Eigen::VectorXd::Zero(mSystem->dimension())),
      mFaceVelocity(std::size_t(MacGrid::fromSpec(cache.grid).faceTotal()), 0.0) {
    if (!(mSettings.dt > 0.0)) throw Error("simulation: dt must be positive");
    if (mSettings.stepsPerFrame < 1) throw Error("simulation: steps per frame must be at least 1");
    const auto cells = std::size_t(mAdvection.smokeGrid().cellCount());
    mFields.density.assign(cells, 0.0);
    mFields.temperature.assign(cells, 0.0);
}

void ReferenceSimulation::setVelocity(const Eigen::VectorXd& v) {
    if (v.size() != mModes) throw Error(sizeMismatch("velocity", v.size(), mModes));
    mState.head(mModes) = v;
}

Eigen::VectorXd ReferenceSimulation::magneticField() const {
    return mSettings.mhd ? Eigen::VectorXd(mState.tail(mModes)) : Eigen::VectorXd();
}

void ReferenceSimulation::setMagneticField(const Eigen::VectorXd& f) {
    if (!mSettings.mhd) Simulator::setMagneticField(f);
    if (f.size() != mModes) throw Error(sizeMismatch("magnetic field", f.size(), mModes));
    mState.tail(mModes) = f;
}

std::vector<double> ReferenceSimulation::faceMagneticField() const {
    if (!mSettings.mhd) return {};
    return reconstructFaceField(mCache, mState.tail(mModes));
}

void ReferenceSimulation::restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) {
    setVelocity(v);
    if (smoke.density.size() != mFields.density.size() || smoke.temperature.size() != mFields.temperature.size())
        throw Error("simulation: saved smoke of " + std::to_string(smoke.density.size()) + " cells, the smoke grid has " +
                    std::to_string(mFields.density.size()));
    mFields = smoke;
    mTime = time;
    mStep = std::lround(time / mSettings.dt);
}

FrameStats ReferenceSimulation::advanceFrame() {
    FrameStats stats;
    const double dt = mSettings.dt;
    for (int s = 0; s < mSettings.stepsPerFrame; ++s) {
        // Buoyancy and splats push the fluid; with MHD the field's half of the force stays 0.
        Eigen::VectorXd force = Eigen::VectorXd::Zero(mState.size());
        if (mSettings.buoyancy != 0.0 || !mSplats.empty()) {
            const BuoyancyInput buoyancy{mSettings.buoyancy, mSettings.smokeScale,
                                         mFields.temperature, mAdvection.fluidMask()};
            force.head(mModes) = projectForce(mCache, forceDensity(mCache, buoyancy, mSplats),
                                              FaceQuantity::Density);
        }
        const StepReport report = mIntegrator.step(mState, dt, force);
        requireFiniteModalState(mState, ++mStep, mTime + dt);
        stats.maxIterations = std::max(stats.maxIterations, report.iterations);
        stats.unconvergedSteps += report.converged ? 0 : 1;
        mFaceVelocity = reconstructFaceField(mCache, velocity());
        if (!mSettings.obstacles.empty()) {
            mState.head(mModes) -= obstacleCorrection(mCache, mFaceVelocity, mSettings.obstacles, mTime + dt);
            mFaceVelocity = reconstructFaceField(mCache, velocity());
        }
        mAdvection.step(std::span<const double>(mFaceVelocity), dt, mSettings.advection,
                        activeEmitters(mSettings.emitters, mTime), mFields);
        mTime += dt;
        ++stats.steps;
    }
    return stats;
}

}  // namespace modeflow
