#include "engine/dynamics/ModalIntegrator.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/dynamics/Gmres.h"
#include "engine/dynamics/ThreadCount.h"

namespace modeflow {

ModalIntegrator::ModalIntegrator(const ModalSystem& system, IntegratorSettings settings)
    : mSystem(system), mSettings(settings), mDecays((system.decayRates().array() != 0.0).any()) {
    if (!(settings.relativeTolerance > 0.0) || settings.maxIterations < 1) {
        throw Error("integrator: the Newton tolerance and iteration limit must be positive");
    }
    if (!(settings.jacobianReuseBelow >= 0.0) || settings.threads < 0 ||
        settings.denseNewtonLimit < 0) {
        throw Error(
            "integrator: the Jacobian reuse threshold, thread count and dense Newton limit "
            "must not be negative");
    }
    if (settings.krylovRestart < 1) throw Error("integrator: the GMRES restart must be positive");
    if (settings.scheme == Integrator::Linearized && !system.freezesRhs())
        throw Error(std::string("integrator: ") + kLinearizedNeedsAFluid);
}

StepReport ModalIntegrator::step(Eigen::VectorXd& x, double h) {
    return advance(x, 0.0, h, nullptr);
}

StepReport ModalIntegrator::step(Eigen::VectorXd& x, double h, const Eigen::VectorXd& force) {
    const ForceFunction constant = [&force](double) { return force; };
    return advance(x, 0.0, h, &constant);
}

StepReport ModalIntegrator::step(Eigen::VectorXd& x, double t, double h,
                                 const ForceFunction& force) {
    return advance(x, t, h, force ? &force : nullptr);
}

StepReport ModalIntegrator::advance(Eigen::VectorXd& x, double t, double h,
                                    const ForceFunction* force) {
    if (x.size() != mSystem.dimension()) {
        throw Error("integrator: the state has " + std::to_string(x.size()) +
                    " entries, the system " + std::to_string(mSystem.dimension()));
    }
    if (!std::isfinite(h)) throw Error("integrator: the time step must be finite");
    const ThreadCount threads(mSettings.threads);
    decay(x, 0.5 * h);
    StepReport report;
    switch (mSettings.scheme) {
        case Integrator::Explicit:
            explicitEuler(x, t, h, force);
            break;
        case Integrator::Rk4:
            rungeKutta4(x, t, h, force);
            break;
        case Integrator::Midpoint:
            report = midpoint(x, t, h, force);
            break;
        case Integrator::Trapezoidal:
            report = trapezoidal(x, t, h, force);
            break;
        case Integrator::Linearized:
            report = linearized(x, t, h, force);
            break;
    }
    decay(x, 0.5 * h);
    return report;
}

void ModalIntegrator::explicitEuler(Eigen::VectorXd& x, double t, double h,
                                    const ForceFunction* force) {
    x += h * velocity(x, t, force);
}

void ModalIntegrator::rungeKutta4(Eigen::VectorXd& x, double t, double h,
                                  const ForceFunction* force) {
    const Eigen::VectorXd k1 = velocity(x, t, force);
    const Eigen::VectorXd k2 = velocity(x + 0.5 * h * k1, t + 0.5 * h, force);
    const Eigen::VectorXd k3 = velocity(x + 0.5 * h * k2, t + 0.5 * h, force);
    const Eigen::VectorXd k4 = velocity(x + h * k3, t + h, force);
    x += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

StepReport ModalIntegrator::midpoint(Eigen::VectorXd& x, double t, double h,
                                     const ForceFunction* force) {
    // Starting from w = x, the first Newton update is the linearly implicit midpoint step.
    Eigen::VectorXd w = x;
    const StepReport report = newton(x, w, h, true, h * forceAt(t + 0.5 * h, force));
    x = w;
    return report;
}

StepReport ModalIntegrator::trapezoidal(Eigen::VectorXd& x, double t, double h,
                                        const ForceFunction* force) {
    Eigen::VectorXd r0;
    mSystem.rhs(x, r0);
    const Eigen::VectorXd f0 = forceAt(t, force);
    const Eigen::VectorXd known = 0.5 * h * (r0 + f0 + forceAt(t + h, force));
    // R(x) is at hand, so the explicit Euler predictor costs nothing.
    Eigen::VectorXd w = x + h * (r0 + f0).cwiseQuotient(mSystem.mass());
    const StepReport report = newton(x, w, h, false, known);
    x = w;
    return report;
}

StepReport ModalIntegrator::linearized(Eigen::VectorXd& x, double t, double h,
                                       const ForceFunction* force) {
    const Eigen::VectorXd& mass = mSystem.mass();
    const Eigen::VectorXd f = forceAt(t + 0.5 * h, force);
    Eigen::VectorXd rate = mHeldRate;  // M⁻¹R near the last step's midpoint, held (see the header)
    if (rate.size() == 0) {
        mSystem.rhs(x, rate);
        rate = rate.cwiseQuotient(mass);
    }
    const Eigen::VectorXd predictor = x + (0.5 * h) * (rate + f.cwiseQuotient(mass));
    mHeldRate.resize(0);  // until this step has converged
    // (I − (h/2)M⁻¹L) ȳ = x + (h/2)M⁻¹f, left-preconditioned by M⁻¹ as the Krylov updates are;
    // solved for the correction δ = ȳ − x̃.
    Eigen::VectorXd frozen;
    const auto product = [&](const Eigen::VectorXd& u, Eigen::VectorXd& out) {
        mSystem.frozenRhs(predictor, u, frozen);
        out = u - (0.5 * h) * frozen.cwiseQuotient(mass);
    };
    Eigen::VectorXd start;
    product(predictor, start);
    const Eigen::VectorXd residual = x + (0.5 * h) * f.cwiseQuotient(mass) - start;
    // Converged when the preconditioned residual is within a tenth of relativeTolerance of |x| (of
    // its own start where x = 0: a force alone): the residual is what the step adds to or takes
    // from the energy, and at relativeTolerance itself the drift over 40 time units of the
    // validate study's disk flow reached 9.3e-13 (2.5e-13 at a tenth, two more GMRES products).
    const double norm = residual.norm();
    if (!std::isfinite(norm))
        throw Error("integrator: the linearized step is no longer finite; reduce dt");
    const double scale = x.norm() > 0.0 ? x.norm() : norm;
    StepReport report;
    report.solver = NewtonSolver::Krylov;
    report.iterations = 1;
    report.residual = scale > 0.0 ? norm / scale : 0.0;
    Eigen::VectorXd delta = Eigen::VectorXd::Zero(x.size());
    if (report.residual > mSettings.relativeTolerance) {
        const GmresResult g =
            gmres(product, residual, delta, 0.1 * mSettings.relativeTolerance * scale / norm,
                  mSettings.krylovRestart, 20 * mSettings.krylovRestart);
        report.jacobianProducts = g.iterations;
        report.converged = g.converged;
        report.residual *= g.residual;
    }
    const Eigen::VectorXd midpoint = predictor + delta;
    // The step's own rate less the force's: M⁻¹L(x̃)ȳ = (2/h)(ȳ − x) − M⁻¹f.
    if (report.converged && h != 0.0)
        mHeldRate = (2.0 / h) * (midpoint - x) - f.cwiseQuotient(mass);
    x = 2.0 * midpoint - x;
    return report;
}

void ModalIntegrator::setHeldRate(const Eigen::VectorXd& rate) {
    if (rate.size() != 0 && rate.size() != mSystem.dimension())
        throw Error("integrator: a held rate of " + std::to_string(rate.size()) +
                    " entries, the system has " + std::to_string(mSystem.dimension()));
    if (!rate.allFinite()) throw Error("integrator: the held rate is not finite");
    if (rate.size() != 0 && mSettings.scheme != Integrator::Linearized)
        throw Error("integrator: only the linearized rule holds a rate between steps");
    mHeldRate = rate;
}

StepReport ModalIntegrator::newton(const Eigen::VectorXd& x, Eigen::VectorXd& w, double h,
                                   bool atMidpoint, const Eigen::VectorXd& constantPart) {
    // Solves G(w) = M(w − x) − c·R(y) − constantPart = 0 with y = (x + w)/2, c = h (midpoint) or
    // y = w, c = h/2 (trapezoidal); in both cases ∂G/∂w = M − (h/2)·∂R/∂y.
    const Eigen::VectorXd& mass = mSystem.mass();
    const double c = atMidpoint ? h : 0.5 * h;
    const double momentum = mass.cwiseProduct(x).norm();
    const double nearSolution = std::sqrt(mSettings.relativeTolerance);
    const bool dense =
        mSystem.formsJacobiansCheaply() && mSystem.dimension() <= mSettings.denseNewtonLimit;
    Eigen::VectorXd y, r, residual;
    Eigen::MatrixXd jac;
    StepReport report;
    report.solver = dense ? NewtonSolver::DenseLu : NewtonSolver::FixedPoint;
    double previous = INFINITY;  // relative residual of the last evaluation
    bool freshJacobian = dense;
    for (;;) {
        y = atMidpoint ? Eigen::VectorXd(0.5 * (x + w)) : w;
        if (freshJacobian) {
            mSystem.linearize(y, r, jac);
        } else {
            mSystem.rhs(y, r);
        }
        residual = mass.cwiseProduct(w - x) - c * r - constantPart;
        const double scale = std::max(momentum, mass.cwiseProduct(w).norm());
        const double norm = residual.norm();
        if (!std::isfinite(norm)) {
            throw Error("integrator: Newton diverged (the state is no longer finite); reduce dt");
        }
        report.residual = scale > 0.0 ? norm / scale : norm;
        if (norm <= mSettings.relativeTolerance * scale) return report;
        // Close to the solution a residual that stops falling is round-off, not slow
        // convergence: further iterations cannot help, so stop there.
        const bool stalled = report.residual >= previous && report.residual <= nearSolution;
        if (report.iterations == mSettings.maxIterations || stalled) {
            report.converged = false;
            return report;
        }
        if (!dense) {
            // Fixed-point updates that do not halve the residual, or would not reach the
            // tolerance within the iteration limit (leaving Newton a few): the step is too stiff
            // for them, Newton–Krylov from here on.
            if (report.solver == NewtonSolver::FixedPoint && report.iterations > 0) {
                const double rate = report.residual / previous;
                const double needed =
                    std::log(mSettings.relativeTolerance / report.residual) / std::log(rate);
                if (rate > 0.5 || report.iterations + needed > mSettings.maxIterations - 5)
                    report.solver = NewtonSolver::Krylov;
            }
            if (report.solver == NewtonSolver::FixedPoint) {
                w -= residual.cwiseQuotient(mass);  // w = x + M⁻¹(c·R(y) + constant part)
            } else {
                // Solve just far enough that this update lands below the tolerance (the
                // quadratic term is then far smaller), but never more loosely than 1e-2.
                const double inner =
                    std::clamp(0.1 * mSettings.relativeTolerance * scale / norm, 1e-12, 1e-2);
                w -= krylovUpdate(y, h, residual, inner, report);
            }
            previous = report.residual;
            ++report.iterations;
            continue;
        }
        if (freshJacobian) {
            jac *= -0.5 * h;
            jac.diagonal() += mass;
            {
                // Eigen would fork threads for each blocked update of this small LU: a net loss
                // at these sizes, and a large one when the machine is busy.
                const ThreadCount serial(1);
                mLu.compute(jac);
            }
            ++report.jacobians;
        }
        // Keep this factorization next time only if it is already accurate to the residual's
        // order and, after a reuse, it still cut the residual by at least 100.
        const bool reusePaidOff = freshJacobian || report.residual <= 0.01 * previous;
        freshJacobian = !(report.residual <= mSettings.jacobianReuseBelow && reusePaidOff);
        previous = report.residual;
        w -= mLu.solve(residual);
        ++report.iterations;
    }
}

Eigen::VectorXd ModalIntegrator::krylovUpdate(const Eigen::VectorXd& y, double h,
                                              const Eigen::VectorXd& residual,
                                              double relativeTolerance, StepReport& report) const {
    // Left-preconditioned by M⁻¹: (I − (h/2)M⁻¹∂R) δ = M⁻¹ residual.
    const Eigen::VectorXd& mass = mSystem.mass();
    Eigen::VectorXd jr;
    const auto product = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
        mSystem.jacobianProduct(y, v, jr);
        out = v - (0.5 * h) * jr.cwiseQuotient(mass);
    };
    Eigen::VectorXd delta;
    const GmresResult g = gmres(product, residual.cwiseQuotient(mass), delta, relativeTolerance,
                                mSettings.krylovRestart, 20 * mSettings.krylovRestart);
    report.jacobianProducts += g.iterations;
    return delta;
}

Eigen::VectorXd ModalIntegrator::velocity(const Eigen::VectorXd& x, double t,
                                          const ForceFunction* force) const {
    Eigen::VectorXd r;
    mSystem.rhs(x, r);
    return (r + forceAt(t, force)).cwiseQuotient(mSystem.mass());
}

Eigen::VectorXd ModalIntegrator::forceAt(double t, const ForceFunction* force) const {
    if (!force) return Eigen::VectorXd::Zero(mSystem.dimension());
    Eigen::VectorXd f = (*force)(t);
    if (f.size() != mSystem.dimension()) {
        throw Error("integrator: the force has " + std::to_string(f.size()) +
                    " entries, the system " + std::to_string(mSystem.dimension()));
    }
    return f;
}

void ModalIntegrator::decay(Eigen::VectorXd& x, double h) const {
    if (!mDecays) return;
    const auto factor = (-h * mSystem.decayRates().array()).exp();
    const Eigen::VectorXd& target = mSystem.decayTargets();
    if (target.size() == 0)
        x.array() *= factor;
    else
        x.array() = target.array() + factor * (x - target).array();
}

}  // namespace modeflow
