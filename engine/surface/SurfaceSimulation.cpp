/// @file SurfaceSimulation.cpp

#include "engine/surface/SurfaceSimulation.h"

#include <algorithm>
#include <string>

#include "engine/core/Error.h"
#include "engine/dynamics/ModalDivergence.h"

namespace modeflow {

SurfaceSimulation::SurfaceSimulation(const BasisCache& cache,
                                     const StructuralCoefficients& coefficients,
                                     const SimulationSettings& settings,
                                     const Eigen::VectorXd& velocity)
    : mDt(settings.dt),
      mStepper(coefficients, settings),
      mDye(cache, settings.emitters),
      mForce(cache) {
    mStepper.setVelocity(velocity);
}

FrameStats SurfaceSimulation::advanceSteps(int steps) {
    FrameStats stats;
    for (int s = 0; s < steps; ++s) {
        const Eigen::VectorXd before = mStepper.velocity();
        const StepReport report = mStepper.step(mDt);
        ++mStep;
        const Eigen::VectorXd after = mStepper.velocity();
        requireFiniteModalState(after, mStep, mTime + mDt);
        mDye.step(before, after, mTime, mDt);
        mTime += mDt;
        ++stats.steps;
        stats.maxIterations = std::max(stats.maxIterations, report.iterations);
        if (!report.converged) ++stats.unconvergedSteps;
    }
    return stats;
}

void SurfaceSimulation::setSplats(std::span<const ForceSplat> splats) {
    mStepper.setForce(mForce.project(splats));
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

}  // namespace modeflow
