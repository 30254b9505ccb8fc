#pragma once
/// @file Diagnostics.h
/// Invariants and monitors of the reduced dynamics. The basis is ⋆2-orthonormal
/// (precompute/README.md), so L² integrals of fields become plain sums over modal coefficients.

#include <Eigen/Core>

namespace modeflow {

/// Kinetic energy ½∫|u|² = ½|v|² (for MHD pass the state [v; F]: ½(|v|² + |F|²)).
double energy(const Eigen::VectorXd& v);

/// LANS-α energy ½∫(|u|² + α²|∇u|²) = ½Σ(1 + α²κ_i²)v_i² (seed §6.3.5).
double lansEnergy(const Eigen::VectorXd& v, const Eigen::VectorXd& kappaSquared, double alpha);

/// Cross helicity ∫u·B = Σ v_i F_i (seed §6.3.5).
double crossHelicity(const Eigen::VectorXd& v, const Eigen::VectorXd& f);

/// Enstrophy ∫ω² = Σ κ_i² v_i² (no ½). Exact for eigenfields of L2 in 2D with free-slip walls,
/// where ∫|∇×Ψ|² = κ², and meaningful as a monitor only there; the truncated dynamics conserves
/// it only approximately (unlike the energy).
double enstrophy(const Eigen::VectorXd& v, const Eigen::VectorXd& kappaSquared);

}  // namespace modeflow
