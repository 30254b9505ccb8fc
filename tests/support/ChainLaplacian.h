#pragma once
/// @file ChainLaplacian.h
/// The eigensolver tests' model operator: the 1D Dirichlet Laplacian on n interior points of
/// [0, 1], K = tridiag(−1, 2, −1)/h with mass h (h = 1/(n+1)), whose simple eigenvalues
/// 4 sin²(jπh/2)/h² are known in closed form.

#include <Eigen/SparseCore>

namespace modeflow::testing {

Eigen::SparseMatrix<double> chainLaplacian(int n);

}  // namespace modeflow::testing
