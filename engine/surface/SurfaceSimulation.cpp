/// @file SurfaceSimulation.cpp

#include "engine/surface/SurfaceSimulation.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/dynamics/ModalDivergence.h"

namespace modeflow {

SurfaceSimulation::SurfaceSimulation(const BasisCache& cache,
                                     const StructuralCoefficients& coefficients,
                                     const SimulationSettings& settings,
                                     const Eigen::VectorXd& velocity)
    : mCache(cache),
      mSettings(settings),
      mStepper(coefficients, settings),
      mDye(cache, settings.emitters) {
    mStepper.setVelocity(velocity);
}

void SurfaceSimulation::advanceSteps(int steps) {
    for (int s = 0; s < steps; ++s) {
        const Eigen::VectorXd before = mStepper.velocity();
        mStepper.step(mSettings.dt);
        ++mStep;
        const Eigen::VectorXd after = mStepper.velocity();
        requireFiniteModalState(after, mStep, mTime + mSettings.dt);
        mDye.step(before, after, mTime, mSettings.dt);
        mTime += mSettings.dt;
    }
}

void SurfaceSimulation::restore(double time, const Eigen::VectorXd& velocity,
                                const Eigen::VectorXd& dye) {
    const Eigen::Index modes = mStepper.modeCount();
    if (velocity.size() != modes)
        throw Error("surface simulation: a velocity of " + std::to_string(velocity.size()) +
                    " modes, expected " + std::to_string(modes));
    mDye.setState(dye);
    mStepper.setVelocity(velocity);
    mTime = time;
}

std::vector<double> SurfaceSimulation::vertexVelocity() const {
    const Eigen::VectorXd u = mCache.surface.vertexVelocity * mStepper.velocity();
    return {u.data(), u.data() + u.size()};
}

}  // namespace modeflow
