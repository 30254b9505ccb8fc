/// @file SurfaceDye.cpp

#include "engine/surface/SurfaceDye.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"

namespace modeflow {

SurfaceDye::SurfaceDye(const BasisCache& cache, std::span<const SmokeEmitter> emitters)
    : mCache(cache),
      mScalars(int(cache.scalar.modes.cols())),
      mSources(cache, emitters),
      mState(Eigen::VectorXd::Zero(mScalars + 1)) {}

void SurfaceDye::step(const Eigen::VectorXd& v0, const Eigen::VectorXd& v1, double t, double h) {
    const Eigen::VectorXd source = mSources.rateAt(t);
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

}  // namespace modeflow
