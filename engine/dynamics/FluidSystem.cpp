#include "engine/dynamics/FluidSystem.h"

#include <optional>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/KappaSquared.h"

namespace modeflow {

namespace {

/// The κ² the parameters use (viscosity or α), checked for n modes (harmonic round-off made 0);
/// none when they use no κ².
std::optional<Eigen::VectorXd> kappaSquaredUsed(const FluidParameters& parameters, int n) {
    if (!(parameters.viscosity >= 0.0) || !(parameters.alpha >= 0.0)) {
        throw Error("fluid dynamics: viscosity and alpha must be non-negative");
    }
    const bool needed = parameters.viscosity > 0.0 || parameters.alpha > 0.0;
    const Eigen::Index given = parameters.kappaSquared.size();
    if ((needed || given != 0) && given != n) {
        throw Error("fluid dynamics: the kappa^2 list has " + std::to_string(given) +
                    " entries for " + std::to_string(n) + " modes" +
                    (needed ? " (viscosity and alpha need one per mode)" : ""));
    }
    if (given == 0) return std::nullopt;
    const Eigen::VectorXd k2 = checkedKappaSquared(parameters.kappaSquared, "fluid dynamics");
    return needed ? std::optional(k2) : std::nullopt;
}

}  // namespace

Eigen::VectorXd FluidSystem::massOf(const FluidParameters& parameters, int n) {
    const double alpha2 = parameters.alpha * parameters.alpha;
    const auto k2 = kappaSquaredUsed(parameters, n);
    return k2 ? Eigen::VectorXd(1.0 + alpha2 * k2->array()) : Eigen::VectorXd::Ones(n);
}

Eigen::VectorXd FluidSystem::decayRatesOf(const FluidParameters& parameters, int n) {
    const auto k2 = kappaSquaredUsed(parameters, n);
    Eigen::VectorXd rates =
        k2 ? Eigen::VectorXd(parameters.viscosity * *k2) : Eigen::VectorXd::Zero(n);
    for (const int k : parameters.held) {
        if (k < 0 || k >= n)
            throw Error("fluid dynamics: held mode " + std::to_string(k + 1) +
                        " is outside the basis of " + std::to_string(n) + " modes");
        rates[k] = 0.0;
    }
    return rates;
}

FluidSystem::FluidSystem(const StructuralCoefficients& coefficients, FluidParameters parameters)
    : mCoefficients(coefficients),
      mFiltered(parameters.alpha != 0.0),
      mMass(massOf(parameters, coefficients.size())),
      mDecay(decayRatesOf(parameters, coefficients.size())),
      mTarget(std::move(parameters.viscousTarget)),
      mHeld(std::move(parameters.held)),
      mLinear(std::move(parameters.linear)) {
    if (mTarget.size() != 0 && mTarget.size() != coefficients.size())
        throw Error("fluid dynamics: viscous targets for " + std::to_string(mTarget.size()) +
                    " modes, the system has " + std::to_string(coefficients.size()));
    if (mLinear && mLinear->size() != coefficients.size())
        throw Error("fluid dynamics: a linear term over " + std::to_string(mLinear->size()) +
                    " modes for " + std::to_string(coefficients.size()) + " modes");
}

void FluidSystem::addLinear(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    if (!mLinear) return;
    Eigen::VectorXd dv;
    mLinear->apply(v, dv);
    out += dv;
}

void FluidSystem::rhs(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    if (mFiltered) {
        mCoefficients.apply(mMass.cwiseProduct(v), v, out);
    } else {
        mCoefficients.apply(v, v, out);
    }
    addLinear(v, out);
    for (const int k : mHeld) out[k] = 0.0;
}

void FluidSystem::frozenRhs(const Eigen::VectorXd& p, const Eigen::VectorXd& u,
                            Eigen::VectorXd& out) const {
    // uᵀC(m, u) = 0 for any m (the k↔j antisymmetry), so L(p) changes ½uᵀMu as R does: by the
    // linear term's uᵀDu alone.
    if (mFiltered) {
        mCoefficients.apply(mMass.cwiseProduct(p), u, out);
    } else {
        mCoefficients.apply(p, u, out);
    }
    addLinear(u, out);
    for (const int k : mHeld) out[k] = 0.0;
}

void FluidSystem::linearize(const Eigen::VectorXd& v, Eigen::VectorXd& out,
                            Eigen::MatrixXd& jac) const {
    // R(v) = apply(Mv, v): ∂R/∂v = byJ(v)·M + byI(Mv), and R = byI(Mv)·v.
    Eigen::MatrixXd byJ;
    if (mFiltered) {
        mCoefficients.linearize(mMass.cwiseProduct(v), v, jac, byJ);
        out.noalias() = jac * v;
        jac += byJ * mMass.asDiagonal();
    } else {
        mCoefficients.linearize(v, v, jac, byJ);
        out.noalias() = jac * v;
        jac += byJ;
    }
    if (mLinear) {
        out.noalias() += mLinear->matrix() * v;
        jac += mLinear->matrix();
    }
    for (const int k : mHeld) {
        out[k] = 0.0;
        jac.row(k).setZero();
    }
}

void FluidSystem::jacobianProduct(const Eigen::VectorXd& v, const Eigen::VectorXd& u,
                                  Eigen::VectorXd& out) const {
    // R(v) = apply(Mv, v) is bilinear: ∂R·u = apply(Mu, v) + apply(Mv, u).
    Eigen::VectorXd second;
    if (mFiltered) {
        mCoefficients.apply(mMass.cwiseProduct(u), v, out);
        mCoefficients.apply(mMass.cwiseProduct(v), u, second);
    } else {
        mCoefficients.apply(u, v, out);
        mCoefficients.apply(v, u, second);
    }
    out += second;
    addLinear(u, out);
}

}  // namespace modeflow
