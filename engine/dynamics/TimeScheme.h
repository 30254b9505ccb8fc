#pragma once
/// @file TimeScheme.h
/// The time integrators of the reduced dynamics (seed §6.3.3, DESIGN §3) and their scene/CLI names.

#include <string_view>

namespace modeflow {

enum class TimeScheme {
    ExplicitEuler,  ///< "explicit": forward Euler, first order, no conservation guarantee
    RungeKutta4,    ///< "rk4": classical fourth-order Runge–Kutta, explicit
    Midpoint,       ///< "midpoint": implicit midpoint, eq. 6.8; energy-preserving, reversible
    Trapezoidal,    ///< "trapezoidal": variational trapezoidal rule, eq. 6.9; reversible
};

/// "explicit", "rk4", "midpoint" or "trapezoidal"; throws modeflow::Error naming the choices.
TimeScheme parseTimeScheme(std::string_view name);
std::string_view timeSchemeName(TimeScheme scheme);

}  // namespace modeflow
