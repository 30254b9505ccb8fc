#pragma once
/// @file Gmres.h
/// Restarted GMRES (Saad & Schultz 1986) for A x = b with A given only as products, the linear
/// solver of Newton–Krylov steps (engine/dynamics/ModalIntegrator.h): Arnoldi with modified
/// Gram–Schmidt, the small least-squares problem by Givens rotations.

#include <functional>

#include <Eigen/Core>

namespace modeflow {

struct GmresResult {
    int iterations = 0;     ///< products with A
    double residual = 0.0;  ///< |b − A x| / |b| at the end
    bool converged = false;
};

/// x ≈ A⁻¹b from x = 0, until |b − Ax| ≤ relativeTolerance·|b| or `maxIterations` products.
/// `product(v, out)` sets out = A v.
GmresResult gmres(const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& product,
                  const Eigen::VectorXd& b, Eigen::VectorXd& x, double relativeTolerance,
                  int restart, int maxIterations);

}  // namespace modeflow
