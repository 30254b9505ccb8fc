#pragma once
/// @file GridCoefficients.h
/// Structural coefficients the way earlier model-reduced solvers evaluated them (the baseline of
/// the coefficients study, seed Fig. 6.16): the advection of one basis field by another,
/// −⟨Ψ_k, (Ψ_i·∇)Ψ_j⟩, sampled on the grid — velocities averaged to cell centres, their gradients
/// by central differences (one-sided next to the wall), summed over the fluid cells with their
/// volume inside Ω. In the continuum this is the same dynamics as seed eq. 6.7; on the grid it
/// is not antisymmetric in k ↔ j, so energy is not conserved by any integrator.

#include <vector>

#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"

namespace modeflow::validate {

/// All N³ entries of a tensor with no symmetry, for the same contractions as the packed storage.
class FullTensorCoefficients final : public StructuralCoefficients {
public:
    /// full[(k·N + i)·N + j] = C[k][i][j].
    FullTensorCoefficients(int n, std::vector<double> full);

    int size() const override { return mN; }
    std::size_t storedBytes() const override { return mFull.size() * sizeof(double); }
    double entry(int k, int i, int j) const override {
        return mFull[(std::size_t(k) * mN + i) * mN + j];
    }
    void apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
               Eigen::VectorXd& out) const override;
    void linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::MatrixXd& byI,
                   Eigen::MatrixXd& byJ) const override;
    void advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                Eigen::VectorXd& out) const override;

    /// max |C[k][i][j] + C[j][i][k]| / max |C|: 0 for exactly antisymmetric coefficients.
    double antisymmetryError() const;

private:
    int mN;
    std::vector<double> mFull;
};

/// −⟨Ψ_k, (Ψ_i·∇)Ψ_j⟩ on the grid for the first `count` velocity modes of `cache` (2D or 3D).
FullTensorCoefficients gridAdvectionCoefficients(const BasisCache& cache, int count);

}  // namespace modeflow::validate
