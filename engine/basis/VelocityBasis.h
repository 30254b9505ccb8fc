#pragma once
/// @file VelocityBasis.h
/// Ψ v and Ψᵀ q of a cache's velocity basis, whichever way it is stored: the dense columns of an
/// eigensolved basis, or the separable transforms of a closed-form one (SeparableTransform.h),
/// whose columns are never formed. What reconstruction, force projection, obstacles and initial
/// states go through.

#include <memory>

#include <Eigen/Core>

#include "engine/basis/SeparableTransform.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

class VelocityBasis {
public:
    /// Keeps a reference to `cache`, which must outlive it.
    /// @throw modeflow::Error when a closed-form basis's DOFs are not the whole box's.
    explicit VelocityBasis(const BasisCache& cache);

    const BasisCache& cache() const { return mCache; }
    int modeCount() const;
    std::int64_t dofCount() const { return std::int64_t(mCache.faces.size()); }
    /// The transforms of a closed-form basis; null for dense columns.
    const SeparableTransform* separable() const { return mSeparable.get(); }

    /// Ψ v: fluxes through the DOF faces (cache.faces order).
    /// @throw modeflow::Error when v is not one value per mode.
    Eigen::VectorXd fluxes(const Eigen::VectorXd& v) const;
    /// Ψᵀ q, q one value per DOF. @throw modeflow::Error when it is not.
    Eigen::VectorXd transposed(const Eigen::VectorXd& q) const;

private:
    const BasisCache& mCache;
    std::unique_ptr<SeparableTransform> mSeparable;
};

}  // namespace modeflow
