#pragma once
/// @file QuadratureSampling.h
/// Products of the vorticity quadrature's maps (BasisCache::Quadrature, elements × face DOFs)
/// with face fluxes: the samples at the elements, and their transposes back onto the faces.
/// What the tensor-free coefficients and the wind's transport around domain walls evaluate.

#include <cstdint>

#include <Eigen/Core>

#include "engine/format/SparseRows.h"

namespace modeflow {

/// out = M·x for rows [first, first + count) of M.
void sampleRows(const SparseRows& m, std::int64_t first, const double* x, double* out,
                std::int64_t count);

/// M·x over every row of M.
Eigen::VectorXd sample(const SparseRows& m, const Eigen::Ref<const Eigen::VectorXd>& x);

/// g += Mᵀ·w.
void addTransposed(const SparseRows& m, const Eigen::VectorXd& w, Eigen::VectorXd& g);

}  // namespace modeflow
