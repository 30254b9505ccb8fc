#pragma once
/// @file Laplacians.h
/// The symmetric positive semi-definite operators of precompute/README.md / seed appendix C.1,
/// assembled from restricted incidence matrices and diagonal stars, so symmetry holds by
/// construction.

#include <Eigen/SparseCore>

#include "precompute/dec/CutCellDec.h"
#include "precompute/dec/DirichletScalarDec.h"

namespace modeflow {

/// L2 with a grad-div penalty: (1+s) dᵀ⋆n d + ⋆(n-1) δ ⋆(n-2)⁻¹ δᵀ ⋆(n-1), δ the curl incidence.
/// Divergence-free fields do not see s; gradient eigenpairs move from μ² to (1+s)μ², out of the
/// low spectrum. s = 0 gives the plain L2. Mass: ⋆(n-1).
Eigen::SparseMatrix<double> velocityLaplacian(const CutCellDec& dec, double penalty);

/// Its curl part alone, ⋆(n-1) δ ⋆(n-2)⁻¹ δᵀ ⋆(n-1): xᵀ K x = ∫|∇×x|², the wall's vorticity
/// included at a no-slip wall (what viscosity dissipates).
Eigen::SparseMatrix<double> velocityCurlCurl(const CutCellDec& dec);

/// L3 = ⋆n d ⋆(n-1)⁻¹ dᵀ ⋆n with no flux through walls (Neumann). Mass: ⋆n.
Eigen::SparseMatrix<double> neumannScalarLaplacian(const CutCellDec& dec);

/// ⋆n d W dᵀ ⋆n with ghost-fluid face weights W (Dirichlet). Mass: ⋆n.
Eigen::SparseMatrix<double> dirichletScalarLaplacian(const DirichletScalarDec& dec);

}  // namespace modeflow
