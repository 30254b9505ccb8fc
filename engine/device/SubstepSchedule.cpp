#include "engine/device/SubstepSchedule.h"

#include <algorithm>
#include <string>

#include "engine/core/Error.h"

namespace modeflow::device {

void SubstepSchedule::reset() {
    mSubsteps = 1;
    mEasySteps = 0;
}

void SubstepSchedule::restore(int substeps, int easySteps) {
    // A power of two up to kMaxSubsteps, as advance() makes them.
    const bool schedule = substeps >= 1 && substeps <= kMaxSubsteps &&
                          (substeps & (substeps - 1)) == 0 && easySteps >= 0 &&
                          easySteps < kEasyStepsToHalve;
    if (!schedule)
        throw Error("simulation: " + std::to_string(substeps) + " modal substeps and " +
                    std::to_string(easySteps) + " easy steps are no schedule of this device");
    mSubsteps = substeps;
    mEasySteps = easySteps;
}

int SubstepSchedule::advance(const DeviceStepStatus& status) {
    const int failed = status.unconvergedSteps - mUnconverged;
    mUnconverged = status.unconvergedSteps;
    if (failed > 0) {
        mSubsteps = std::min(2 * mSubsteps, kMaxSubsteps);
        mEasySteps = 0;
    } else if (mSubsteps > 1 && status.iterations <= 8 && ++mEasySteps >= kEasyStepsToHalve) {
        mSubsteps /= 2;
        mEasySteps = 0;
    }
    return failed;
}

StepCarry carryOf(const ModalStepper& stepper, const SubstepSchedule& schedule) {
    return {stepper.heldRate(), stepper.warmStart(), schedule.substeps(), schedule.easySteps()};
}

void restoreCarry(const StepCarry& carry, ModalStepper& stepper, SubstepSchedule& schedule) {
    schedule.restore(carry.substeps, carry.easySteps);
    stepper.setHeldRate(carry.heldRate);
    stepper.setWarmStart(carry.warmRhs);
}

}  // namespace modeflow::device
