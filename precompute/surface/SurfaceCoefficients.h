#pragma once
/// @file SurfaceCoefficients.h
/// The structural coefficients C[k][i][j] = ∫ ω_i (u_k × u_j)·n dA (seed eq. 6.7 on a surface:
/// the vorticity and the cross product are normal to it) of a surface's velocity modes.
///
/// Vorticity lives at vertices (ω = −⋆0⁻¹d0ᵀ⋆1 Ψ), velocities are constant per triangle
/// (SurfaceDec.h), and each triangle t contributes (A_t/3)(ω_a + ω_b + ω_c) times the cross
/// product of u_k and u_j in its own tangent plane — the barycentric ⋆0 split of the triangle
/// among its corners. Only k < j is computed (engine/core/PackedLayout.h), so C is exactly
/// antisymmetric in k ↔ j.

#include <vector>

#include <Eigen/Core>

#include "precompute/surface/SurfaceDec.h"

namespace modeflow {

/// Packed k < j coefficients of the columns of `modes` (edge fluxes).
std::vector<double> assembleSurfaceCoefficients(const SurfaceDec& dec, const TriangleMesh& mesh,
                                                const Eigen::MatrixXd& modes);

}  // namespace modeflow
