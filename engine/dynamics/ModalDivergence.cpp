#include "engine/dynamics/ModalDivergence.h"

#include "engine/core/NumberText.h"

namespace modeflow {

ModalStateDiverged::ModalStateDiverged(long step, double time)
    : Error("the modal state diverged at step " + std::to_string(step) +
            " (t = " + numberText(time, 6) + ")"),
      mStep(step),
      mTime(time) {}

void requireFiniteModalState(const Eigen::VectorXd& state, long step, double time) {
    if (!state.allFinite()) throw ModalStateDiverged(step, time);
}

std::string divergenceAdvice(const ModalStateDiverged& diverged, std::string_view integrator,
                             std::string_view dtSetting) {
    return std::string(diverged.what()) + "; " + std::string(integrator) +
           " is unstable at this step size: lower " + std::string(dtSetting) + " or use midpoint";
}

}  // namespace modeflow
