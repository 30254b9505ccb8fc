#include "engine/format/ModeMaterialization.h"

#include <string>

#include "engine/core/AvailableMemory.h"

namespace modeflow {

double velocityModeBytes(std::int64_t faces, std::int64_t modes) {
    return double(faces) * double(modes) * double(sizeof(double));
}

Eigen::MatrixXd materializedVelocityModes(const BasisCache& cache) {
    const BasisCache::Velocity& v = cache.velocity;
    const auto faces = std::int64_t(cache.faces.size());
    const auto modes = std::int64_t(v.separable.size());
    requireMemory(velocityModeBytes(faces, modes),
                  "the closed-form velocity basis (" + std::to_string(modes) + " modes on " +
                      std::to_string(faces) + " faces)",
                  "materializing its dense columns for the run",
                  "lower the velocity modes in [basis] or [grid].resolution");
    return velocityModeFluxes(cache.grid, cache.faces, v.separable);
}

void materializeVelocityModes(BasisCache& cache) {
    BasisCache::Velocity& v = cache.velocity;
    if (v.source != BasisSource::ClosedForm || v.modes.cols() == Eigen::Index(v.separable.size()))
        return;
    v.modes = materializedVelocityModes(cache);
}

}  // namespace modeflow
