#pragma once
/// @file EnergyBudget.h
/// The energy identity of the midpoint rule with a linear term D (a wind's transport): since
/// vᵀC(v, v) = 0, a step changes ½|v|² by exactly h v̄ᵀ D v̄, v̄ the step's midpoint state.

#include <functional>

#include <Eigen/Core>

#include "engine/dynamics/LinearModalTerm.h"
#include "engine/dynamics/ModalIntegrator.h"

namespace modeflow::testing {

/// A random state of `n` modes with energy ½|v|² = 1 (normal amplitudes, seeded).
Eigen::VectorXd unitEnergyState(int n, unsigned seed);

/// How far a midpoint run's energy strayed from its budget, relative to the starting energy.
struct EnergyBudget {
    double worstStep = 0.0;  ///< max over the steps of |ΔE − h v̄ᵀDv̄|
    double drift = 0.0;      ///< |Σ (ΔE − h v̄ᵀDv̄)|
};

/// Takes `steps` steps of `h` with `integrator` (the midpoint rule) from `v`, holding each step's
/// energy change against h v̄ᵀ `term` v̄; `eachStep(v̄, D v̄)` sees every step's midpoint.
EnergyBudget midpointEnergyBudget(
    ModalIntegrator& integrator, const LinearModalTerm& term, Eigen::VectorXd& v, double h,
    int steps,
    const std::function<void(const Eigen::VectorXd&, const Eigen::VectorXd&)>& eachStep = {});

}  // namespace modeflow::testing
