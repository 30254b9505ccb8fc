#include "engine/dynamics/ModalDivergence.h"

#include <cmath>
#include <limits>

#include "engine/core/NumberText.h"

namespace modeflow {

ModalStateDiverged::ModalStateDiverged(long step, double time)
    : Error("the modal state diverged at step " + std::to_string(step) +
            " (t = " + numberText(time, 6) + ")"),
      mStep(step),
      mTime(time) {}

double largestSteppableNorm() {
    static const double largest = std::pow(std::numeric_limits<double>::max(), 0.25);
    return largest;
}

void requireFiniteModalState(const Eigen::VectorXd& state, long step, double time) {
    // stableNorm() does not overflow before the state does.
    if (!state.allFinite() || state.stableNorm() > largestSteppableNorm())
        throw ModalStateDiverged(step, time);
}

std::string divergenceAdvice(const ModalStateDiverged& diverged, std::string_view integrator,
                             std::string_view dtSetting) {
    // The implicit rules are the advice for the explicit ones; for themselves, only a smaller step.
    const bool implicit =
        integrator == "midpoint" || integrator == "trapezoidal" || integrator == "linearized";
    return std::string(diverged.what()) + "; " + std::string(integrator) +
           " is unstable at this step size: lower " + std::string(dtSetting) +
           (implicit ? "" : " or use midpoint");
}

}  // namespace modeflow
