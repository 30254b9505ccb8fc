#pragma once
/// @file BasisComparison.h
/// How far apart two eigenbases of the same operators are, for tests that compare solvers: a
/// degenerate eigenspace holds any orthonormal basis of itself, so vectors compare by spans.

#include <Eigen/Core>

namespace modeflow::testing {

/// Largest relative difference of two ascending eigenvalue lists (equal entries, the exact zeros
/// of harmonic fields among them, count as equal).
double eigenvalueDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

/// Largest ‖B_g − A_g A_gᵀ M B_g‖∞ / ‖B_g‖∞ over the groups g of eigenvalues closer than 1e-3
/// relative (nearly degenerate vectors turn into each other with round-off); A and B have
/// M-orthonormal columns, `values` are A's eigenvalues.
double spanDifference(const Eigen::VectorXd& values, const Eigen::MatrixXd& a,
                      const Eigen::MatrixXd& b, const Eigen::VectorXd& mass);

}  // namespace modeflow::testing
