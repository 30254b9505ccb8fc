/// @file SurfaceSimulator.cpp

#include "engine/simulation/SurfaceSimulator.h"

#include <algorithm>

namespace modeflow {

std::vector<double> surfaceDyeAtVertices(const BasisCache& cache, const Eigen::VectorXd& dye) {
    const Eigen::MatrixXd& modes = cache.scalar.modes;
    const Eigen::VectorXd values =
        Eigen::VectorXd::Constant(modes.rows(), dye[0]) + modes * dye.tail(modes.cols());
    return {values.data(), values.data() + values.size()};
}

std::vector<double> surfaceVelocityAtVertices(const BasisCache& cache,
                                              const Eigen::VectorXd& velocity) {
    const Eigen::VectorXd u = cache.surface.vertexVelocity * velocity;
    return {u.data(), u.data() + u.size()};
}

double dyeColourScale(const SimulationSettings& settings) {
    double rate = 0.0;
    for (const SmokeEmitter& e : settings.emitters) rate = std::max(rate, e.densityRate);
    return rate > 0.0 ? rate * settings.dt * settings.stepsPerFrame * 4.0 : 1.0;
}

}  // namespace modeflow
