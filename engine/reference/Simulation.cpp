#include "engine/reference/Simulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/reference/ForceField.h"
#include "engine/reference/ForceProjection.h"
#include "engine/reference/ObstacleCorrection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/simulation/Combustion.h"
#include "engine/simulation/SmokeDisplacement.h"
#include "engine/simulation/WindTransport.h"

namespace modeflow::reference {

Simulation::Simulation(const BasisCache& cache, const StructuralCoefficients& coefficients,
                       SimulationSettings settings, std::vector<std::uint8_t> smokeMask)
    : mCache(cache),
      mBasis(cache),
      mSettings(withWindTransport(std::move(settings), cache)),
      mStepper(coefficients, mSettings),
      mAdvection(MacGrid::fromSpec(cache.grid), mSettings.smokeScale, std::move(smokeMask)),
      mDisplacement(mAdvection.smokeGrid(), mAdvection.fluidMask()),
      mParticles(airGridOf(cache.grid, mSettings.wind), mAdvection.smokeGrid(),
                 mAdvection.fluidMask(), mSettings.particles, mSettings.shotEnd),
      mFaceVelocity(std::size_t(MacGrid::fromSpec(cache.grid).faceTotal()), 0.0) {
    if (!(mSettings.dt > 0.0)) throw Error("simulation: dt must be positive");
    if (mSettings.stepsPerFrame < 1) throw Error("simulation: steps per frame must be at least 1");
    setObstacles(mSettings.obstacles);
    if (mSettings.wind) {
        mAdvection.setWind(*mSettings.wind);
        mWindField = windBaseFlow(cache, *mSettings.wind);
        mFaceVelocity = mWindField;
    }
    requireInflowsMeetFluid(mAdvection.outsideAir(), mSettings.inflows, mAdvection.fluidMask());
    const auto cells = std::size_t(mAdvection.smokeGrid().cellCount());
    mFields.density.assign(cells, 0.0);
    mFields.temperature.assign(cells, 0.0);
    if (mSettings.fire) {
        mFields.fuel.assign(cells, 0.0);
        mFields.flame.assign(cells, 0.0);
    }
}

std::vector<double> Simulation::faceMagneticField() const {
    if (!mSettings.mhd) return {};
    return reconstructFaceField(mBasis, mStepper.magneticField());
}

void Simulation::restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) {
    setVelocity(v);
    if (smoke.density.size() != mFields.density.size() ||
        smoke.temperature.size() != mFields.temperature.size())
        throw Error("simulation: saved smoke of " + std::to_string(smoke.density.size()) +
                    " cells, the smoke grid has " + std::to_string(mFields.density.size()));
    if (smoke.fuel.size() != mFields.fuel.size() || smoke.flame.size() != mFields.flame.size())
        throw Error(mSettings.fire ? "simulation: the saved smoke carries no fuel and flame; the "
                                     "run burns fuel ([fire])"
                                   : "simulation: the saved smoke carries fuel; the run has no "
                                     "[fire]");
    mFields = smoke;
    mParticles.restore({});
    mTime = time;
    mStep = std::lround(time / mSettings.dt);
}

void Simulation::setObstacles(std::vector<MovingObstacle> obstacles) {
    if (obstacles.size() > std::size_t(maxObstacles))
        throw Error("simulation: " + std::to_string(obstacles.size()) + " obstacles, at most " +
                    std::to_string(maxObstacles) + " move at once");
    requireDisplaceableMotion(obstacles, mSettings.dt, mAdvection.smokeGrid());
    mSettings.obstacles = std::move(obstacles);
}

void Simulation::setEmitters(std::vector<SmokeEmitter> emitters) {
    requireEmitterCount(emitters);
    mSettings.emitters = std::move(emitters);
}

void Simulation::setViscosity(double viscosity) {
    mStepper.setViscosity(viscosity);
    mSettings.fluid.viscosity = viscosity;
}

void Simulation::setIntegrator(Integrator integrator) {
    mStepper.setIntegrator(integrator);
    mSettings.integrator = integrator;
}

void Simulation::reconstructAirVelocity() {
    mFaceVelocity = reconstructFaceField(mBasis, velocity());
    for (std::size_t f = 0; f < mWindField.size(); ++f) mFaceVelocity[f] += mWindField[f];
}

FrameStats Simulation::advanceSteps(int steps) {
    FrameStats stats;
    const double dt = mSettings.dt;
    for (int s = 0; s < steps; ++s) {
        // Buoyancy and splats push the fluid.
        Eigen::VectorXd force = Eigen::VectorXd::Zero(mStepper.modeCount());
        if (mSettings.buoyancy != 0.0 || !mSplats.empty()) {
            const BuoyancyInput buoyancy{mSettings.buoyancy, mSettings.smokeScale,
                                         mFields.temperature, mAdvection.fluidMask()};
            force = projectForce(mBasis, forceDensity(mCache, buoyancy, mSplats),
                                 FaceQuantity::Density);
        }
        mStepper.setForce(force);
        const StepReport report = mStepper.step(dt);
        requireFiniteModalState(mStepper.state(), ++mStep, mTime + dt);
        stats.maxIterations = std::max(stats.maxIterations, report.iterations);
        stats.unconvergedSteps += report.converged ? 0 : 1;
        reconstructAirVelocity();
        const std::vector<MovingObstacle> regions = mSettings.velocityRegions(mTime);
        if (!regions.empty()) {
            // The solids hold the air's velocity, the wind's included, to their own.
            mStepper.correctVelocity(
                -obstacleCorrection(mBasis, mFaceVelocity, regions, mTime + dt));
            reconstructAirVelocity();
        }
        if (mActiveInflows.changes(mSettings.inflows, mTime))
            mAdvection.setInflows(activeInflows(mSettings.inflows, mTime));
        mAdvection.step(std::span<const double>(mFaceVelocity), dt, mSettings.advection,
                        activeEmitters(mSettings.emitters, mTime), mFields);
        mDisplacement.step(mSettings.obstacles, mTime, dt, mFields);
        if (mSettings.fire) burn(*mSettings.fire, mAdvection.fluidMask(), dt, mFields);
        mParticles.step(mFaceVelocity, mSettings.obstacles, mTime, dt);
        mTime += dt;
        ++stats.steps;
    }
    return stats;
}

}  // namespace modeflow::reference
