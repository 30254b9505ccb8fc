#pragma once
/// @file SurfaceAdvection.h
/// What a surface run needs of its bases besides the structural coefficients: the spectral dye
/// advection operators (seed eq. 6.2) and each velocity mode's velocity at the vertices.

#include <Eigen/Core>

#include "precompute/surface/SurfaceDec.h"

namespace modeflow {

/// A_m,ij = ∫ Φ_i (Ψ_m · ∇Φ_j) dA for the scalar modes (columns of `scalarModes`, vertex values,
/// linear on each triangle) and the velocity modes (columns of `velocityModes`, edge fluxes):
/// each triangle contributes A_t · mean_t(Φ_i) · u_m(t)·∇Φ_j(t), exact for the piecewise-linear
/// Φ. Divergence-free Ψ_m make A_m antisymmetric; it is stored as ½(A_ij − A_ji) for i < j, one
/// row per pair in the row order of engine/core/PackedLayout.h, one column per velocity mode.
Eigen::MatrixXd surfaceAdvection(const SurfaceDec& dec, const TriangleMesh& mesh,
                                 const Eigen::MatrixXd& scalarModes,
                                 const Eigen::MatrixXd& velocityModes);

/// The velocity of each mode at the vertices, 3 rows (x, y, z) per vertex: the area-weighted
/// mean of the constant velocities of the triangles around it.
Eigen::MatrixXd surfaceVertexVelocity(const SurfaceDec& dec, const TriangleMesh& mesh,
                                      const Eigen::MatrixXd& velocityModes);

}  // namespace modeflow
