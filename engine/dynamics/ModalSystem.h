#pragma once
/// @file ModalSystem.h
/// A reduced model in the form the integrators advance:
///
///     M ẋ = R(x) + f(t),   then   ẋ_i = −r_i (x_i − t_i)   (operator split)
///
/// with a constant diagonal mass M (ones for Euler and MHD, 1 + α²κ² for LANS-α), a quadratic
/// right-hand side R built from the structural coefficients (seed eq. 6.6), its analytic Jacobian
/// for Newton, and decay rates r (νκ² for viscosity, seed §6.3.5) towards targets t (0, or a
/// wind's held flow's Stokes correction: FluidSystem.h) applied as exact exponentials.

#include <Eigen/Core>

#include "engine/core/Error.h"

namespace modeflow {

class ModalSystem {
public:
    virtual ~ModalSystem() = default;

    /// Length of the state x.
    virtual int dimension() const = 0;
    /// Diagonal of M.
    virtual const Eigen::VectorXd& mass() const = 0;
    /// Decay rates r_i ≥ 0.
    virtual const Eigen::VectorXd& decayRates() const = 0;
    /// What each x_i decays toward; empty for all 0.
    virtual const Eigen::VectorXd& decayTargets() const { return kNoTargets; }
    /// out = R(x).
    virtual void rhs(const Eigen::VectorXd& x, Eigen::VectorXd& out) const = 0;
    /// out = R(x) and jac = ∂R/∂x, in as few passes over the coefficients as possible.
    virtual void linearize(const Eigen::VectorXd& x, Eigen::VectorXd& out,
                           Eigen::MatrixXd& jac) const = 0;
    /// out = (∂R/∂x)(x)·u without forming the Jacobian (matrix-free Newton–Krylov): R is
    /// quadratic, so this is a few contractions, O(stored coefficients).
    virtual void jacobianProduct(const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                                 Eigen::VectorXd& out) const = 0;
    /// Whether frozenRhs exists: for fluids, not for MHD (the linearized rule,
    /// engine/dynamics/ModalIntegrator.h).
    virtual bool freezesRhs() const { return false; }
    /// out = L(p)·u, the right-hand side with its first factor frozen at p: a linear operator in u
    /// with L(x)·x = R(x) and uᵀL(p)u = 0 for every u (uᵀDu with a linear term D, FluidSystem.h).
    /// One contraction.
    /// @throw modeflow::Error unless freezesRhs().
    virtual void frozenRhs(const Eigen::VectorXd& p, const Eigen::VectorXd& u,
                           Eigen::VectorXd& out) const;
    /// Whether linearize costs about a contraction (stored coefficients); false when forming the
    /// Jacobian costs far more (tensor-free: O(E·N²)), so that solvers use jacobianProduct.
    virtual bool formsJacobiansCheaply() const { return true; }

private:
    static inline const Eigen::VectorXd kNoTargets{};
};

inline void ModalSystem::frozenRhs(const Eigen::VectorXd&, const Eigen::VectorXd&,
                                   Eigen::VectorXd&) const {
    throw Error("integrator: this system has no frozen right-hand side");
}

}  // namespace modeflow
