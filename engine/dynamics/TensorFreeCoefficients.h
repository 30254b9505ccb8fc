#pragma once
/// @file TensorFreeCoefficients.h
/// The structural coefficients (seed eq. 6.7) evaluated without storing them: every contraction
/// reconstructs the fluxes of its vectors from the modes Ψ (V faces × N), samples the weighted
/// vorticity and the velocity at the vorticity elements with the quadrature of the assembly
/// (BasisCache::Quadrature: Ω = w∘curl, B = u_b, Q = u_c, each elements × faces), and projects
/// back:
///
///     C[k][i][j] = Σ_e (ΩΨ)_ei ((BΨ)_ek (QΨ)_ej − (QΨ)_ek (BΨ)_ej)
///     apply(a, b) = Ψᵀ (Bᵀ(ω_a ∘ q_b) − Qᵀ(ω_a ∘ p_b)),  ω_a = ΩΨa, p_b = BΨb, q_b = QΨb
///     advect(u, x) = Ψᵀ Ωᵀ(p_u ∘ q_x − q_u ∘ p_x)
///
/// the same numbers as the assembled tensor up to round-off, in O(N·V) per contraction (two
/// passes over Ψ) instead of O(N³), and no N³ assembly. C[k][i][j] = −C[j][i][k] holds by
/// construction (the cross product), so vᵀ apply(a, v) = 0 exactly: the energy identity. The
/// dense Jacobian (linearize) costs O(E·N²) and is meant for small N; large systems use
/// Jacobian–vector products, which are two contractions.

#include <cstddef>

#include <Eigen/Core>

#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

class TensorFreeCoefficients final : public StructuralCoefficients {
public:
    /// Keeps references to `modes` (V × N ⋆-orthonormal fluxes) and `quadrature`, which must
    /// outlive it.
    /// @throw modeflow::Error when the quadrature's three maps differ in rows, or reference a face
    ///        beyond the modes' rows, or there are no modes.
    TensorFreeCoefficients(const Eigen::MatrixXd& modes, const BasisCache::Quadrature& quadrature);

    int size() const override { return int(mModes.cols()); }
    /// The modes (read twice a contraction) and the quadrature.
    std::size_t storedBytes() const override;
    double entry(int k, int i, int j) const override;
    void apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
               Eigen::VectorXd& out) const override;
    void linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::MatrixXd& byI,
                   Eigen::MatrixXd& byJ) const override;
    void advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                Eigen::VectorXd& out) const override;
    /// False: linearize is O(E·N²) where apply is O(N·V).
    bool linearizesCheaply() const override { return false; }

private:
    /// The fluxes Ψ·[a b] (one pass over Ψ for both), or Ψa alone when b = a.
    Eigen::MatrixXd fluxes(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;

    const Eigen::MatrixXd& mModes;
    const BasisCache::Quadrature& mQuadrature;
};

}  // namespace modeflow
