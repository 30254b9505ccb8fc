#pragma once
/// @file FluidSystem.h
/// The reduced Euler / Navier–Stokes / LANS-α model over the modal velocity v (engine/README.md,
/// "Reduced dynamics"):
///
///     (1 + α²κ_k²) v̇_k = Σ_ij (1 + α²κ_i²) C[k][i][j] v_i v_j + f_k,
///     then  v_k ← c_k + e^{−νκ_k²h} (v_k − c_k).
///
/// With α = 0 this is seed eq. 6.6. With α > 0 it is the LANS-α model of seed §6.3.5: the left side
/// is the momentum m_k = (1 + α²κ_k²) v_k, forces act on m, and the energy ½Σ(1 + α²κ_i²)v_i² is
/// conserved because vᵀ apply(m, v) = 0 by the k↔j antisymmetry — for the midpoint rule too, as the
/// identity holds at the midpoint state. κ² may come in any order (frequency-shaped bases).
///
/// c = 0, or the Stokes correction of a wind's held flow round [[domain]] walls: viscosity acts on
/// the whole velocity B + Ψv, and ν Δ B projected on the modes is νκ²c (B's slip along a no-slip
/// wall is vorticity; engine/README.md "Wind").
///
/// A linear term D v (a wind's advection of the modes, LinearModalTerm.h) joins the right-hand
/// side: (1 + α²κ_k²) v̇_k = … + (D v)_k. The energy then changes by exactly h v̄ᵀ D v̄ a midpoint
/// step (v̄ the midpoint state), what D's boundary puts in or takes out.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/LinearModalTerm.h"
#include "engine/dynamics/ModalSystem.h"
#include "engine/dynamics/StructuralCoefficients.h"

namespace modeflow {

struct FluidParameters {
    /// κ_i² of each basis mode; needed when viscosity or alpha is non-zero. Checked by
    /// checkedKappaSquared (engine/core/KappaSquared.h): harmonic round-off counts as 0.
    Eigen::VectorXd kappaSquared;
    double viscosity = 0.0;  ///< ν
    double alpha = 0.0;      ///< LANS-α filter length
    /// 0-based modes held at their amplitudes ([forcing]): v̇_k = 0 and no viscous decay for
    /// them, while they keep acting on the others (a forcing that feeds energy in).
    std::vector<int> held{};
    /// A constant linear term D v of the right-hand side (a wind), or none.
    std::shared_ptr<const LinearModalTerm> linear{};
    /// c, what viscosity relaxes each mode toward (a wind's held flow), or empty for 0.
    Eigen::VectorXd viscousTarget{};
};

class FluidSystem final : public ModalSystem {
public:
    /// The mass 1 + α²κ_i² and decay rates νκ_i² of n modes (LANS-α, viscosity; seed §6.3.5),
    /// held modes decaying at 0.
    /// @throw modeflow::Error for negative ν or α, a κ² list that is needed but not n long, a
    /// κ² that checkedKappaSquared refuses, or a held mode outside [0, n).
    static Eigen::VectorXd massOf(const FluidParameters& parameters, int n);
    static Eigen::VectorXd decayRatesOf(const FluidParameters& parameters, int n);

    /// Keeps a reference to `coefficients`, which must outlive the system. Throws
    /// modeflow::Error for negative parameters, a κ² list of the wrong length, or a linear term
    /// of another size than the coefficients.
    FluidSystem(const StructuralCoefficients& coefficients, FluidParameters parameters = {});

    int dimension() const override { return mCoefficients.size(); }
    const Eigen::VectorXd& mass() const override { return mMass; }
    const Eigen::VectorXd& decayRates() const override { return mDecay; }
    const Eigen::VectorXd& decayTargets() const override { return mTarget; }
    void rhs(const Eigen::VectorXd& v, Eigen::VectorXd& out) const override;
    void linearize(const Eigen::VectorXd& v, Eigen::VectorXd& out,
                   Eigen::MatrixXd& jac) const override;
    void jacobianProduct(const Eigen::VectorXd& v, const Eigen::VectorXd& u,
                         Eigen::VectorXd& out) const override;
    bool freezesRhs() const override { return true; }
    /// L(p)·u = C(Mp, u) + D u, held modes' rows 0.
    void frozenRhs(const Eigen::VectorXd& p, const Eigen::VectorXd& u,
                   Eigen::VectorXd& out) const override;
    bool formsJacobiansCheaply() const override { return mCoefficients.linearizesCheaply(); }

private:
    /// out += D v, when there is a linear term.
    void addLinear(const Eigen::VectorXd& v, Eigen::VectorXd& out) const;

    const StructuralCoefficients& mCoefficients;
    bool mFiltered = false;  ///< α > 0, so the mass is not the identity
    Eigen::VectorXd mMass;
    Eigen::VectorXd mDecay;
    Eigen::VectorXd mTarget;
    std::vector<int> mHeld;
    std::shared_ptr<const LinearModalTerm> mLinear;
};

}  // namespace modeflow
