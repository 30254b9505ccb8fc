#include "engine/dynamics/FluidSystem.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {

namespace {

/// Whether the parameters use κ² (viscosity or α), after checking them for n modes.
bool needsKappa(const FluidParameters& parameters, int n) {
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
    if (given != 0 && (parameters.kappaSquared.array() < 0.0).any()) {
        throw Error("fluid dynamics: kappa^2 values must be non-negative");
    }
    return needed;
}

}  // namespace

Eigen::VectorXd FluidSystem::massOf(const FluidParameters& parameters, int n) {
    const double alpha2 = parameters.alpha * parameters.alpha;
    return needsKappa(parameters, n) ? Eigen::VectorXd(1.0 + alpha2 * parameters.kappaSquared.array())
                                     : Eigen::VectorXd::Ones(n);
}

Eigen::VectorXd FluidSystem::decayRatesOf(const FluidParameters& parameters, int n) {
    return needsKappa(parameters, n) ? Eigen::VectorXd(parameters.viscosity * parameters.kappaSquared)
                                     : Eigen::VectorXd::Zero(n);
}

FluidSystem::FluidSystem(const StructuralCoefficients& coefficients, FluidParameters parameters)
    : mCoefficients(coefficients),
      mFiltered(parameters.alpha != 0.0),
      mMass(massOf(parameters, coefficients.size())),
      mDecay(decayRatesOf(parameters, coefficients.size())) {}

void FluidSystem::rhs(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    if (mFiltered) {
        mCoefficients.apply(mMass.cwiseProduct(v), v, out);
    } else {
        mCoefficients.apply(v, v, out);
    }
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
}

}  // namespace modeflow
