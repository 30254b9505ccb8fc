#include "engine/dynamics/MhdSystem.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/KappaSquared.h"

namespace modeflow {

MhdSystem::MhdSystem(const StructuralCoefficients& coefficients, MhdParameters parameters)
    : mCoefficients(coefficients), mLorentzForce(parameters.lorentzForce) {
    const int n = coefficients.size();
    if (!(parameters.viscosity >= 0.0) || !(parameters.magneticDiffusivity >= 0.0)) {
        throw Error("MHD dynamics: viscosity and magnetic diffusivity must be non-negative");
    }
    const bool needsKappa = parameters.viscosity > 0.0 || parameters.magneticDiffusivity > 0.0;
    const Eigen::Index given = parameters.kappaSquared.size();
    if ((needsKappa || given != 0) && given != n) {
        throw Error("MHD dynamics: the kappa^2 list has " + std::to_string(given) +
                    " entries for " + std::to_string(n) + " modes");
    }
    const Eigen::VectorXd k2 = given != 0
                                   ? checkedKappaSquared(parameters.kappaSquared, "MHD dynamics")
                                   : Eigen::VectorXd();
    mMass = Eigen::VectorXd::Ones(2 * n);
    mDecay = Eigen::VectorXd::Zero(2 * n);
    if (needsKappa) mDecay << parameters.viscosity * k2, parameters.magneticDiffusivity * k2;
}

Eigen::VectorXd MhdSystem::state(const Eigen::VectorXd& v, const Eigen::VectorXd& f) const {
    const int n = mCoefficients.size();
    if (v.size() != n || f.size() != n) {
        throw Error("MHD dynamics: velocity and field need " + std::to_string(n) +
                    " coefficients each, got " + std::to_string(v.size()) + " and " +
                    std::to_string(f.size()));
    }
    Eigen::VectorXd x(2 * n);
    x << v, f;
    return x;
}

void MhdSystem::rhs(const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
    const int n = mCoefficients.size();
    const Eigen::VectorXd v = x.head(n), f = x.tail(n);
    Eigen::VectorXd fluid, induction;
    mCoefficients.apply(v, v, fluid);
    mCoefficients.advect(v, f, induction);
    if (mLorentzForce) {
        Eigen::VectorXd lorentz;
        mCoefficients.apply(f, f, lorentz);
        fluid -= lorentz;
    }
    out.resize(2 * n);
    out << fluid, induction;
}

void MhdSystem::linearize(const Eigen::VectorXd& x, Eigen::VectorXd& out,
                          Eigen::MatrixXd& jac) const {
    // With S(a) = byI and M(b) = byJ of StructuralCoefficients::linearize:
    //   vᵀC v = S(v)v, FᵀC F = S(F)F, the induction term is −M(v)ᵀF (it is linear in F), so
    //   ∂v̇/∂v = S(v) + M(v), ∂v̇/∂F = −S(F) − M(F), ∂Ḟ/∂v = M(F)ᵀ, ∂Ḟ/∂F = −M(v)ᵀ.
    const int n = mCoefficients.size();
    const Eigen::VectorXd v = x.head(n), f = x.tail(n);
    Eigen::MatrixXd sv, mv, sf, mf;
    mCoefficients.linearize(v, v, sv, mv);
    mCoefficients.linearize(f, f, sf, mf);
    out.resize(2 * n);
    out.head(n).noalias() = sv * v;
    if (mLorentzForce) out.head(n).noalias() -= sf * f;
    out.tail(n).noalias() = -mv.transpose() * f;
    jac.resize(2 * n, 2 * n);
    jac.topLeftCorner(n, n) = sv + mv;
    if (mLorentzForce)
        jac.topRightCorner(n, n) = -(sf + mf);
    else
        jac.topRightCorner(n, n).setZero();
    jac.bottomLeftCorner(n, n) = mf.transpose();
    jac.bottomRightCorner(n, n) = -mv.transpose();
}

void MhdSystem::jacobianProduct(const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                                Eigen::VectorXd& out) const {
    // Every term is bilinear: ∂(vᵀCv − FᵀCF)·(du, dF) = C(du, v) + C(v, du) − C(dF, F) − C(F, dF),
    // ∂advect(v, F)·(du, dF) = advect(du, F) + advect(v, dF).
    const int n = mCoefficients.size();
    const Eigen::VectorXd v = x.head(n), f = x.tail(n), du = u.head(n), df = u.tail(n);
    Eigen::VectorXd fluid, term, induction;
    mCoefficients.apply(du, v, fluid);
    mCoefficients.apply(v, du, term);
    fluid += term;
    if (mLorentzForce) {
        mCoefficients.apply(df, f, term);
        fluid -= term;
        mCoefficients.apply(f, df, term);
        fluid -= term;
    }
    mCoefficients.advect(du, f, induction);
    mCoefficients.advect(v, df, term);
    induction += term;
    out.resize(2 * n);
    out << fluid, induction;
}

}  // namespace modeflow
