#pragma once
/// @file StructuralCoefficients.h
/// The structural coefficients C[k][i][j] = ∫(∇×Ψi)·(Ψk×Ψj) of seed eq. 6.7 and the three
/// contractions the reduced dynamics needs. Every storage keeps only k < j and relies on the exact
/// antisymmetry C[k][i][j] = −C[j][i][k], which is what makes the midpoint rule conserve energy.

#include <cstddef>

#include <Eigen/Core>

namespace modeflow {

class StructuralCoefficients {
public:
    virtual ~StructuralCoefficients() = default;

    /// N, the number of velocity modes.
    virtual int size() const = 0;
    /// Bytes of coefficient data one contraction streams (values and indices).
    virtual std::size_t storedBytes() const = 0;
    /// C[k][i][j] for any k, i, j in [0, N).
    virtual double entry(int k, int i, int j) const = 0;

    /// out_k = Σ_ij C[k][i][j] a_i b_j (the right-hand side of eq. 6.6 is apply(v, v)).
    virtual void apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                       Eigen::VectorXd& out) const = 0;

    /// Both partial contractions, in one pass over the coefficients:
    ///   byI(k,j) = Σ_i C[k][i][j] a_i   (= ∂apply(a,b)/∂b, antisymmetric),
    ///   byJ(k,i) = Σ_j C[k][i][j] b_j   (= ∂apply(a,b)/∂a).
    /// apply(a, b) = byI·b = byJ·a, and the Jacobian of v ↦ vᵀC_k v is byI + byJ at a = b = v.
    virtual void linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::MatrixXd& byI,
                           Eigen::MatrixXd& byJ) const = 0;

    /// out_k = Σ_ij C[j][k][i] x_i u_j: the Lie advection of a field x (a magnetic field, a
    /// spectral Kelvin loop) by the velocity u (seed §6.3.5 MHD, appendix C.3).
    virtual void advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                        Eigen::VectorXd& out) const = 0;

    /// Whether linearize costs about as much as apply (true for stored coefficients).
    virtual bool linearizesCheaply() const { return true; }

    /// Jacobian of f(v)_k = vᵀC_k v, and f(v) itself, in one pass.
    void jacobian(const Eigen::VectorXd& v, Eigen::MatrixXd& jac, Eigen::VectorXd& f) const;

protected:
    /// Throws modeflow::Error naming the operation unless `a` has N entries.
    void checkSize(const char* operation, const Eigen::VectorXd& a) const;
};

}  // namespace modeflow
