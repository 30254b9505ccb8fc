#pragma once
/// @file ModalForce.h
/// External modal forces f_k = Ψkᵀ⋆2 F (engine/README.md, "Reduced dynamics") as a function of
/// time, for schemes that sample the force inside a step (RK4 stages, the midpoint time, the
/// trapezoidal end points).

#include <functional>

#include <Eigen/Core>

namespace modeflow {

/// f(t), a vector of the system's dimension.
using ForceFunction = std::function<Eigen::VectorXd(double t)>;

}  // namespace modeflow
