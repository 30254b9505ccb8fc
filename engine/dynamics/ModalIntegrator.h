#pragma once
/// @file ModalIntegrator.h
/// Advances a ModalSystem M ẋ = R(x) + f(t) by one step h with the chosen Integrator:
///
///   explicit     x' = x + h M⁻¹(R(x) + f(t))
///   rk4          classical Runge–Kutta with forces sampled at t, t + h/2, t + h
///   midpoint     M(x' − x) = h (R((x + x')/2) + f(t + h/2))                       (seed eq. 6.8)
///   trapezoidal  M(x' − x) = h/2 (R(x) + R(x')) + h/2 (f(t) + f(t + h))           (seed eq. 6.9)
///   linearized   M(x' − x) = h (L(x̃)·(x + x')/2 + f(t + h/2)),  x̃ = x + h/2 (g + M⁻¹f(t + h/2))
///
/// The linearized rule is the midpoint rule with the right-hand side's first factor frozen at an
/// explicit predictor x̃ of the midpoint (ModalSystem::frozenRhs: R(y) = C(My, y) becomes
/// C(Mx̃, y)): linear in x', so it costs one pass over the coefficients (L(x̃) once) however many
/// iterations its linear solve takes, where the midpoint rule contracts anew at every iteration.
/// The predictor's rate g is the free rate M⁻¹L(x̃)ȳ of the step before, held between steps
/// (heldRate(): (2/h)(ȳ − x) − M⁻¹f, no contraction), or M⁻¹R(x) for the first step or after the
/// rate was dropped (a second pass): either is within O(h) of the rate at x, so x̃ is within
/// O(h²) of the midpoint and the rule is second order. L(x̃) is antisymmetric like R's Jacobian
/// part, so the energy ½xᵀMx is conserved exactly as by the midpoint rule whatever x̃ is. It is
/// not time-reversible (x̃ is explicit). Its linear system, (M − (h/2)L(x̃)) ȳ = Mx + (h/2)f for
/// the midpoint ȳ = (x + x')/2, is solved by GMRES from ȳ = x̃ to relativeTolerance / 10. The held
/// rate is the fluid's own (forces and the decay are outside it), so forces that change between
/// steps and changes of x between steps (obstacles) leave it valid; a new state from elsewhere (a
/// run restored, an interactive reset) calls for dropHeldRate(), and a resumed run restores it
/// (setHeldRate) to continue bit for bit.
///
/// The implicit equations are solved by Newton until |residual| ≤ relativeTolerance ·
/// max(|Mx|, |Mx'|), whichever linear solver takes the Newton updates, so that both conserve the
/// energy alike. Up to denseNewtonLimit unknowns the system's analytic Jacobian is formed and
/// factorized (LU, N³/3 flops and N² doubles). Above, or when the system forms Jacobians at a
/// high cost (tensor-free coefficients, ModalSystem::formsJacobiansCheaply), nothing N² is formed:
/// fixed-point iterations w ← x + M⁻¹(c·R(y) + f) (one contraction each) while each cuts the
/// residual at least in half, which at the usual steps (h|∂R| ≲ 0.3) takes a handful; if one does
/// not, Newton–Krylov from there: each update solved matrix-free by GMRES on Jacobian–vector
/// products (two contractions each), preconditioned by the diagonal mass. With the dense Jacobian:
/// once the residual is below jacobianReuseBelow, the iterates move so little that the last
/// factorized Jacobian is as good as a fresh one (the error it adds is that residual times a factor
/// of order h|C||v|), so the next evaluation computes the residual alone: a lighter pass over the
/// coefficients and no new LU. A step whose reused Jacobian stops paying off goes back to fresh
/// ones. The decay rates (viscosity) are applied exactly, x_i ← e^{−r_i h/2} x_i before and after
/// the step (Strang splitting, which keeps the second order of the implicit rules; a mode with R =
/// 0 decays exactly as e^{−r h}). A negative h runs the step backwards; the implicit rules are then
/// exactly reversible.

#include <Eigen/Core>
#include <Eigen/LU>

#include "engine/core/SceneSpec.h"
#include "engine/dynamics/ModalForce.h"
#include "engine/dynamics/ModalSystem.h"
#include "engine/dynamics/StepReport.h"

namespace modeflow {

/// Why a model without ModalSystem::frozenRhs (MHD) cannot take the linearized rule.
inline constexpr const char* kLinearizedNeedsAFluid =
    "the linearized rule is for fluids (Euler, Navier–Stokes, LANS-α); MHD takes midpoint, "
    "trapezoidal, explicit or rk4";

struct IntegratorSettings {
    Integrator scheme = Integrator::Midpoint;
    /// Newton residual, relative to the momentum |Mx|. At 1e-13 the accepted residual already
    /// leaves a systematic energy error of ~3e-15 per midpoint step (3e-11 over 10⁴ steps of a
    /// random N = 50 state); 1e-14 brings that to round-off for ~10% more passes.
    double relativeTolerance = 1e-14;
    int maxIterations = 20;            ///< Newton iterations before giving up on a step
    double jacobianReuseBelow = 1e-4;  ///< relative residual below which the Jacobian is kept
    /// OpenMP threads for the contractions during a step; 0 keeps OpenMP's default
    /// (OMP_NUM_THREADS). More threads raise the bandwidth of large contractions (about 2× at
    /// N ≥ 200 on two idle cores), but on a machine busy with other processes every fork/join
    /// waits for a descheduled thread and steps get several times slower, hence the default 1.
    int threads = 1;
    /// Newton with a dense LU of the Jacobian up to this many unknowns; fixed-point iterations,
    /// then Newton–Krylov if they stall, above (an LU at N = 2000 costs ~3 GFLOP per Jacobian, a
    /// contraction of the sparse box coefficients tens of milliseconds).
    int denseNewtonLimit = 400;
    int krylovRestart = 50;  ///< GMRES restart length (Krylov vectors kept)
};

class ModalIntegrator {
public:
    /// Keeps a reference to `system`, which must outlive the integrator. Throws modeflow::Error
    /// for a non-positive tolerance or iteration limit, negative other settings, or the
    /// linearized rule for a system without a frozen right-hand side (MHD).
    ModalIntegrator(const ModalSystem& system, IntegratorSettings settings = {});

    const IntegratorSettings& settings() const { return mSettings; }

    /// One unforced step.
    StepReport step(Eigen::VectorXd& x, double h);
    /// One step with a force held constant over the step.
    StepReport step(Eigen::VectorXd& x, double h, const Eigen::VectorXd& force);
    /// One step from time t with a time-dependent force.
    StepReport step(Eigen::VectorXd& x, double t, double h, const ForceFunction& force);

    /// The linearized rule's rate held for the next step's predictor (see above); empty before
    /// the first step, after an unconverged one, with another scheme, or once dropped.
    const Eigen::VectorXd& heldRate() const { return mHeldRate; }
    /// Restores a held rate (a resumed run), or drops it with an empty vector.
    /// @throw modeflow::Error on a wrong size, a non-finite rate, or a rate for another scheme.
    void setHeldRate(const Eigen::VectorXd& rate);
    void dropHeldRate() { mHeldRate.resize(0); }

private:
    /// The whole step: half decay, the scheme with `force` (null: none), half decay.
    StepReport advance(Eigen::VectorXd& x, double t, double h, const ForceFunction* force);
    void explicitEuler(Eigen::VectorXd& x, double t, double h, const ForceFunction* force);
    void rungeKutta4(Eigen::VectorXd& x, double t, double h, const ForceFunction* force);
    StepReport midpoint(Eigen::VectorXd& x, double t, double h, const ForceFunction* force);
    StepReport trapezoidal(Eigen::VectorXd& x, double t, double h, const ForceFunction* force);
    StepReport linearized(Eigen::VectorXd& x, double t, double h, const ForceFunction* force);
    /// Newton on the midpoint or trapezoidal equation; see the .cpp.
    StepReport newton(const Eigen::VectorXd& x, Eigen::VectorXd& w, double h, bool atMidpoint,
                      const Eigen::VectorXd& constantPart);
    /// The Newton update of a matrix-free step: (M − (h/2)∂R/∂y(y)) δ = residual, by GMRES to
    /// `relativeTolerance` of |residual|.
    Eigen::VectorXd krylovUpdate(const Eigen::VectorXd& y, double h,
                                 const Eigen::VectorXd& residual, double relativeTolerance,
                                 StepReport& report) const;
    /// M⁻¹(R(x) + f(t)).
    Eigen::VectorXd velocity(const Eigen::VectorXd& x, double t, const ForceFunction* force) const;
    /// f(t) checked for size, or zero without a force.
    Eigen::VectorXd forceAt(double t, const ForceFunction* force) const;
    void decay(Eigen::VectorXd& x, double h) const;

    const ModalSystem& mSystem;
    IntegratorSettings mSettings;
    bool mDecays = false;
    Eigen::PartialPivLU<Eigen::MatrixXd> mLu;
    Eigen::VectorXd mHeldRate;  ///< the linearized rule's g, empty when none is held
};

}  // namespace modeflow
