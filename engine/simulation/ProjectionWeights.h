#pragma once
/// @file ProjectionWeights.h
/// The weight each velocity DOF gets when a grid quantity is projected on the basis,
/// f_k = Σ_d Ψ_k[d] w_d q_d (engine/reference/ForceProjection.h says why): shared by both
/// backends, which project with the same weights.

#include <Eigen/Core>

#include "engine/format/BasisCache.h"

namespace modeflow {

enum class FaceQuantity {
    Density,    ///< force per unit volume along the normal: w = h_axis
    FaceField,  ///< flux per whole face area: w = faceArea(axis) × ⋆
};

/// w_d for every DOF (cache.faces order).
Eigen::VectorXd projectionWeights(const BasisCache& cache, FaceQuantity quantity);

}  // namespace modeflow
