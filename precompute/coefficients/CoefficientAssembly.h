#pragma once
/// @file CoefficientAssembly.h
/// The structural coefficients C[k][i][j] = ∫(∇×Ψi)·(Ψk×Ψj) (seed eq. 6.7, engine/README.md,
/// "Reduced dynamics") of a velocity basis on a cut-cell grid, by quadrature over the vorticity
/// elements (3D edges, 2D vertices).
///
/// At each element e (axis a; b, c the next axes in cyclic order; in 2D a = z, b = x, c = y):
///   ω_i(e)  = (∂_b u_c − ∂_c u_b)(e): circulation of ⋆Ψi around the dual face / its area,
///   u_b, u_c: the mean velocity of the two b-normal and the two c-normal faces touching e,
///   C[k][i][j] += w_e ω_i(e) (u_kb u_jc − u_kc u_jb),   w_e = |e ∩ Ω| · |dual of e|.
/// The cross product makes C exactly antisymmetric in k ↔ j; only k < j is computed and stored,
/// in the packed layout of engine/core/PackedLayout.h.
///
/// The three linear maps (face fluxes → w_e ω, u_b, u_c) are the quadrature a cache stores
/// (BasisCache::Quadrature): the assembly runs on it, and so does the runtime's tensor-free
/// advection, so both see the same numbers.

#include <vector>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "precompute/dec/CutCellDec.h"
#include "precompute/dec/CutCellMeasures.h"

namespace modeflow {

/// The quadrature of every vorticity element with a positive weight, element type by type;
/// columns are the face DOFs of `dec`.
BasisCache::Quadrature vorticityQuadrature(const CubicalComplex& complex,
                                           const CutCellMeasures& measures, const CutCellDec& dec);

/// Packed k < j coefficients of the columns of `modes` (face fluxes on the quadrature's columns).
/// Cost: N²(N−1)/2 · E multiply-adds, run as blocked matrix products.
std::vector<double> assembleStructuralCoefficients(const BasisCache::Quadrature& quadrature,
                                                   const Eigen::MatrixXd& modes);

/// The same, with the quadrature of `complex`, `measures` and `dec`.
std::vector<double> assembleStructuralCoefficients(const CubicalComplex& complex,
                                                   const CutCellMeasures& measures,
                                                   const CutCellDec& dec,
                                                   const Eigen::MatrixXd& modes);

/// packed(:, pair(k,j)) += Ωᵀ R(k,j) with R_e(k,j) = P_ek Q_ej − Q_ek P_ej: the quadrature of
/// ω_i (u_k × u_j)·n at elements e (rows) whose weighted vorticity is Ω and whose velocity
/// components along two orthonormal tangent directions are P and Q (one column per mode). In
/// blocks of pairs so the products are matrix-matrix (cache friendly, threaded by Eigen). Also
/// the surfaces' assembly (precompute/surface/SurfaceCoefficients.h).
void accumulateCrossProducts(const Eigen::MatrixXd& omega, const Eigen::MatrixXd& p,
                             const Eigen::MatrixXd& q, std::vector<double>& packed);

}  // namespace modeflow
