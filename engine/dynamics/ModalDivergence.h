#pragma once
/// @file ModalDivergence.h
/// A modal state that stopped being finite: an integrator unstable at its step size (the explicit
/// rule and RK4 blow up once h·|∂R/∂v| is too large). Every simulator checks the state after each
/// step, before it reaches the grid, so that a diverged run stops with this message rather than
/// with NaN positions in the smoke sampling.

#include <string>
#include <string_view>

#include <Eigen/Core>

#include "engine/core/Error.h"

namespace modeflow {

class ModalStateDiverged : public Error {
public:
    /// "the modal state diverged at step S (t = T)".
    ModalStateDiverged(long step, double time);
    long step() const { return mStep; }
    double time() const { return mTime; }

private:
    long mStep;
    double mTime;
};

/// The largest |v| a step can take: |v|⁴ must be finite, because a step takes norms of the
/// quadratic term C·v·v (about 1.2e77).
double largestSteppableNorm();

/// @throw ModalStateDiverged when `state` (v, or [v; F] with MHD) has a NaN or infinite entry
/// after step `step` (counted from t = 0), at time `time`, or a norm above
/// largestSteppableNorm(): still finite, but the next step and the face velocity a frame
/// reconstructs from it would overflow.
void requireFiniteModalState(const Eigen::VectorXd& state, long step, double time);

/// The message for a user: the error's own, then "; <integrator> is unstable at this step size:
/// lower <dtSetting> or use midpoint" ("or use midpoint" left out when it is already midpoint or
/// trapezoidal; `integrator`: the scene keyword; `dtSetting`: where the user sets the step,
/// "[simulation].dt" or "--dt").
std::string divergenceAdvice(const ModalStateDiverged& diverged, std::string_view integrator,
                             std::string_view dtSetting);

}  // namespace modeflow
