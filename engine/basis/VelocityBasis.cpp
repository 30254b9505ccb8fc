#include "engine/basis/VelocityBasis.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {

VelocityBasis::VelocityBasis(const BasisCache& cache) : mCache(cache) {
    if (cache.velocity.source == BasisSource::ClosedForm)
        mSeparable = std::make_unique<SeparableTransform>(cache);
}

int VelocityBasis::modeCount() const {
    return mSeparable ? mSeparable->modeCount() : int(mCache.velocity.modes.cols());
}

Eigen::VectorXd VelocityBasis::fluxes(const Eigen::VectorXd& v) const {
    if (v.size() != modeCount())
        throw Error("reconstruction: " + std::to_string(v.size()) +
                    " coefficients for a basis of " + std::to_string(modeCount()) + " modes");
    return mSeparable ? mSeparable->fluxes(v) : Eigen::VectorXd(mCache.velocity.modes * v);
}

Eigen::VectorXd VelocityBasis::transposed(const Eigen::VectorXd& q) const {
    if (q.size() != dofCount())
        throw Error("force projection: " + std::to_string(q.size()) +
                    " face values for a basis on " + std::to_string(dofCount()) + " faces");
    return mSeparable ? mSeparable->transposed(q)
                      : Eigen::VectorXd(mCache.velocity.modes.transpose() * q);
}

}  // namespace modeflow
