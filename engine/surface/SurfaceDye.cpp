/// @file SurfaceDye.cpp

#include "engine/surface/SurfaceDye.h"

#include <algorithm>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"

namespace modeflow {

SurfaceDye::SurfaceDye(const BasisCache& cache, std::span<const SmokeEmitter> emitters)
    : mCache(cache), mScalars(int(cache.scalar.modes.cols())) {
    if (cache.kind != BasisKind::Surface) throw Error("surface dye: the basis is not a surface's");
    const Eigen::VectorXd& area = cache.scalar.cellStar;  // ⋆0
    mState = Eigen::VectorXd::Zero(mScalars + 1);
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

void SurfaceDye::step(const Eigen::VectorXd& v0, const Eigen::VectorXd& v1, double t, double h) {
    Eigen::VectorXd source = Eigen::VectorXd::Zero(mScalars + 1);
    for (const Source& s : mSources)
        if (s.emitter.activeAt(t)) source += s.emitter.densityRate * s.projection;
    mState[0] += h * source[0];
    if (mScalars == 0) return;
    const Eigen::VectorXd pairs = mCache.surface.advection * (0.5 * (v0 + v1));
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(mScalars, mScalars);
    const auto m = std::size_t(mScalars);
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 1; j < m; ++j) {
            const double a = pairs[Eigen::Index(pairIndex(m, i, j))];
            k(Eigen::Index(i), Eigen::Index(j)) = a;
            k(Eigen::Index(j), Eigen::Index(i)) = -a;
        }
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(mScalars, mScalars);
    const Eigen::VectorXd f = mState.tail(mScalars);
    const Eigen::VectorXd rhs = f - 0.5 * h * (k * f) + h * source.tail(mScalars);
    mState.tail(mScalars) = (identity + 0.5 * h * k).partialPivLu().solve(rhs);
}

void SurfaceDye::setState(const Eigen::VectorXd& state) {
    if (state.size() != mState.size())
        throw Error("surface dye: a state of " + std::to_string(state.size()) +
                    " values, expected " + std::to_string(mState.size()));
    mState = state;
}

std::vector<double> SurfaceDye::vertexValues() const {
    const Eigen::VectorXd values =
        Eigen::VectorXd::Constant(mCache.scalar.modes.rows(), mState[0]) +
        mCache.scalar.modes * mState.tail(mScalars);
    return {values.data(), values.data() + values.size()};
}

double dyeColourScale(const SimulationSettings& settings) {
    double rate = 0.0;
    for (const SmokeEmitter& e : settings.emitters) rate = std::max(rate, e.densityRate);
    return rate > 0.0 ? rate * settings.dt * settings.stepsPerFrame * 4.0 : 1.0;
}

}  // namespace modeflow
