#pragma once
/// @file StepReport.h
/// What one integrator step reports. Explicit schemes report zero iterations and residual.

namespace modeflow {

/// How an implicit step was solved (engine/dynamics/ModalIntegrator.h): Newton with a dense LU
/// of the Jacobian; fixed-point iterations alone; or fixed-point iterations that stopped
/// contracting, finished by Newton–Krylov.
enum class NewtonSolver { None, DenseLu, FixedPoint, Krylov };

struct StepReport {
    /// Newton iterations (updates of the state) the implicit scheme took.
    int iterations = 0;
    /// Jacobians evaluated and factorized; the other iterations reused the last one.
    int jacobians = 0;
    /// |residual| of the scheme's equation at the accepted state, relative to |M x|.
    double residual = 0.0;
    /// false if Newton stopped at the iteration limit or stalled above the tolerance (the state is
    /// still the best iterate, so the caller may go on, warn, or reduce the step).
    bool converged = true;
    /// Krylov: products with the Jacobian (two contractions each) over all iterations.
    int jacobianProducts = 0;
    /// None for the explicit schemes.
    NewtonSolver solver = NewtonSolver::None;
};

}  // namespace modeflow
