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
      mSystem(coefficients, settings.fluid),
      mIntegrator(mSystem, IntegratorSettings{settings.integrator}),
      mDye(cache, settings.emitters),
      mVelocity(velocity) {}

void SurfaceSimulation::advanceFrame() {
    for (int s = 0; s < mSettings.stepsPerFrame; ++s) {
        const Eigen::VectorXd before = mVelocity;
        mIntegrator.step(mVelocity, mSettings.dt);
        ++mStep;
        requireFiniteModalState(mVelocity, mStep, mTime + mSettings.dt);
        mDye.step(before, mVelocity, mTime, mSettings.dt);
        mTime += mSettings.dt;
    }
}

void SurfaceSimulation::restore(double time, const Eigen::VectorXd& velocity,
                                const Eigen::VectorXd& dye) {
    if (velocity.size() != mVelocity.size())
        throw Error("surface simulation: a velocity of " + std::to_string(velocity.size()) +
                    " modes, expected " + std::to_string(mVelocity.size()));
    mDye.setState(dye);
    mVelocity = velocity;
    mTime = time;
}

std::vector<double> SurfaceSimulation::vertexVelocity() const {
    const Eigen::VectorXd u = mCache.surface.vertexVelocity * mVelocity;
    return {u.data(), u.data() + u.size()};
}

}  // namespace modeflow
