/// @file SurfaceSources.cpp

#include "engine/simulation/SurfaceSources.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {

SurfaceSources::SurfaceSources(const BasisCache& cache, std::span<const SmokeEmitter> emitters)
    : mScalars(int(cache.scalar.modes.cols())) {
    if (cache.kind != BasisKind::Surface) throw Error("surface dye: the basis is not a surface's");
    const Eigen::VectorXd& area = cache.scalar.cellStar;  // ⋆0
    for (std::size_t e = 0; e < emitters.size(); ++e) {
        Eigen::VectorXd inside = Eigen::VectorXd::Zero(area.size());
        for (Eigen::Index v = 0; v < inside.size(); ++v)
            inside[v] =
                emitters[e].contains(cache.surface.mesh.vertices[std::size_t(v)], 3) ? 1.0 : 0.0;
        if (inside.sum() == 0.0)
            throw Error("[[source]] #" + std::to_string(e + 1) +
                        " covers no vertex of the surface: move it onto the surface or enlarge it");
        Source source{emitters[e], Eigen::VectorXd(mScalars + 1)};
        const Eigen::VectorXd weighted = area.cwiseProduct(inside);
        source.projection[0] = weighted.sum() / area.sum();
        source.projection.tail(mScalars) = cache.scalar.modes.transpose() * weighted;
        mSources.push_back(std::move(source));
    }
}

Eigen::VectorXd SurfaceSources::rateAt(double t) const {
    Eigen::VectorXd rate = Eigen::VectorXd::Zero(mScalars + 1);
    for (const Source& s : mSources)
        if (s.emitter.activeAt(t)) rate += s.emitter.densityRate * s.projection;
    return rate;
}

}  // namespace modeflow
