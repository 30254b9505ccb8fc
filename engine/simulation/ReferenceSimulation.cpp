#include "engine/simulation/ReferenceSimulation.h"

#include <algorithm>

#include "engine/field/ForceProjection.h"
#include "engine/field/VelocityReconstruction.h"
#include "engine/format/Error.h"

namespace modeflow {

ReferenceSimulation::ReferenceSimulation(const BasisCache& cache,
                                         const StructuralCoefficients& coefficients,
                                         SimulationSettings settings,
                                         std::vector<std::uint8_t> smokeMask)
    : mCache(cache),
      mSettings(std::move(settings)),
      mSystem(coefficients, mSettings.fluid),
      mIntegrator(mSystem, IntegratorSettings{mSettings.integrator}),
      mAdvection(MacGrid::fromSpec(cache.grid), mSettings.smokeScale, std::move(smokeMask)),
      mVelocity(Eigen::VectorXd::Zero(coefficients.size())),
      mFaceVelocity(std::size_t(MacGrid::fromSpec(cache.grid).faceTotal()), 0.0) {
    if (!(mSettings.dt > 0.0)) throw Error("simulation: dt must be positive");
    if (mSettings.stepsPerFrame < 1) throw Error("simulation: steps per frame must be at least 1");
    const auto cells = std::size_t(mAdvection.smokeGrid().cellCount());
    mFields.density.assign(cells, 0.0);
    mFields.temperature.assign(cells, 0.0);
}

void ReferenceSimulation::setVelocity(const Eigen::VectorXd& v) {
    if (v.size() != mVelocity.size())
        throw Error("simulation: velocity of " + std::to_string(v.size()) +
                    " modes, the basis has " + std::to_string(mVelocity.size()));
    mVelocity = v;
}

void ReferenceSimulation::restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) {
    setVelocity(v);
    if (smoke.density.size() != mFields.density.size() || smoke.temperature.size() != mFields.temperature.size())
        throw Error("simulation: saved smoke of " + std::to_string(smoke.density.size()) + " cells, the smoke grid has " +
                    std::to_string(mFields.density.size()));
    mFields = smoke;
    mTime = time;
}

FrameStats ReferenceSimulation::advanceFrame() {
    FrameStats stats;
    const double dt = mSettings.dt;
    for (int s = 0; s < mSettings.stepsPerFrame; ++s) {
        Eigen::VectorXd force = Eigen::VectorXd::Zero(mVelocity.size());
        if (mSettings.buoyancy != 0.0 || !mSplats.empty()) {
            const BuoyancyInput buoyancy{mSettings.buoyancy, mSettings.smokeScale,
                                         mFields.temperature, mAdvection.fluidMask()};
            force = projectForce(mCache, forceDensity(mCache, buoyancy, mSplats),
                                 FaceQuantity::Density);
        }
        const StepReport report = mIntegrator.step(mVelocity, dt, force);
        stats.maxIterations = std::max(stats.maxIterations, report.iterations);
        stats.unconvergedSteps += report.converged ? 0 : 1;
        mFaceVelocity = reconstructFaceField(mCache, mVelocity);
        if (!mSettings.obstacles.empty()) {
            mVelocity -= obstacleCorrection(mCache, mFaceVelocity, mSettings.obstacles, mTime + dt);
            mFaceVelocity = reconstructFaceField(mCache, mVelocity);
        }
        mAdvection.step(std::span<const double>(mFaceVelocity), dt, mSettings.advection,
                        activeEmitters(mSettings.emitters, mTime), mFields);
        mTime += dt;
        ++stats.steps;
    }
    return stats;
}

}  // namespace modeflow
