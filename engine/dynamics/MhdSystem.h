#pragma once
/// @file MhdSystem.h
/// Ideal (or resistive) incompressible MHD in one divergence-free basis (seed §6.3.5), over the
/// state x = [v; F] of the velocity and magnetic-field coefficients:
///
///     v̇_k = vᵀC_k v − FᵀC_k F + f_k,     Ḟ_k = Σ_ij F_i v_j C[j][k][i],
///
/// then v_k ← e^{−νκ_k²h} v_k and F_k ← e^{−ηκ_k²h} F_k. The energy ½(|v|² + |F|²) and the cross
/// helicity Σ v_i F_i are conserved: both follow from C[k][i][j] = −C[j][i][k] alone, and as they
/// are quadratic the midpoint rule keeps them exactly. A force vector has 2N entries (the second
/// half drives F and is normally zero).

#include <Eigen/Core>

#include "engine/dynamics/ModalSystem.h"
#include "engine/dynamics/StructuralCoefficients.h"

namespace modeflow {

struct MhdParameters {
    /// κ_i² of each basis mode; needed when a diffusivity is non-zero. Checked by
    /// checkedKappaSquared (engine/core/KappaSquared.h): harmonic round-off counts as 0.
    Eigen::VectorXd kappaSquared;
    double viscosity = 0.0;            ///< ν, damping v
    double magneticDiffusivity = 0.0;  ///< η, damping F
    /// false: F is only carried by the flow and does not act back on it (the Lorentz term
    /// −FᵀC_k F is dropped). F is then a spectral Kelvin loop Γ = Σγ_i⋆A_i (appendix C.3), whose
    /// pairing Σ v_i γ_i with the velocity is the conserved circulation, or a passive field.
    bool lorentzForce = true;
};

class MhdSystem final : public ModalSystem {
public:
    /// Keeps a reference to `coefficients`, which must outlive the system. Throws
    /// modeflow::Error for negative diffusivities or a κ² list of the wrong length.
    MhdSystem(const StructuralCoefficients& coefficients, MhdParameters parameters = {});

    /// The state [v; F]; throws modeflow::Error unless both have N entries.
    Eigen::VectorXd state(const Eigen::VectorXd& v, const Eigen::VectorXd& f) const;

    int dimension() const override { return 2 * mCoefficients.size(); }
    const Eigen::VectorXd& mass() const override { return mMass; }
    const Eigen::VectorXd& decayRates() const override { return mDecay; }
    void rhs(const Eigen::VectorXd& x, Eigen::VectorXd& out) const override;
    void linearize(const Eigen::VectorXd& x, Eigen::VectorXd& out,
                   Eigen::MatrixXd& jac) const override;
    void jacobianProduct(const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                         Eigen::VectorXd& out) const override;
    bool formsJacobiansCheaply() const override { return mCoefficients.linearizesCheaply(); }

private:
    const StructuralCoefficients& mCoefficients;
    bool mLorentzForce = true;
    Eigen::VectorXd mMass;
    Eigen::VectorXd mDecay;
};

}  // namespace modeflow
