#pragma once
/// @file SubstepSchedule.h
/// How many modal substeps a device step takes (device::Simulation, device::SurfaceSimulation):
/// doubled, up to kMaxSubsteps, when an implicit solve fails to converge (a failed substep keeps
/// its state, so nothing blows up), and halved again after a long run of easy steps, once the
/// flow has calmed down. The float32 fixed-point iteration needs this where the CPU reference's
/// Newton iteration does not; a checkpoint carries the schedule (StepCarry).

#include "engine/device/ModalStepper.h"
#include "engine/simulation/StepCarry.h"

namespace modeflow::device {

class SubstepSchedule {
public:
    static constexpr int kMaxSubsteps = 16;
    /// Steps of at most 8 iterations after which the substeps are halved again.
    static constexpr int kEasyStepsToHalve = 50;

    int substeps() const { return mSubsteps; }
    int easySteps() const { return mEasySteps; }

    /// Back to one substep (a state set from the host).
    void reset();
    /// A saved schedule (StepCarry::substeps, easySteps).
    /// @throw modeflow::Error for one advance() cannot make.
    void restore(int substeps, int easySteps);
    /// The schedule after a step whose stepper reports `status`: returns the substeps of that
    /// step that failed to converge.
    int advance(const DeviceStepStatus& status);

private:
    int mSubsteps = 1;
    int mEasySteps = 0;
    int mUnconverged = 0;  ///< the stepper's count of failed substeps so far
};

/// What a device simulation's steps carry (StepCarry.h): the stepper's held rate and warm start,
/// and the schedule.
StepCarry carryOf(const ModalStepper& stepper, const SubstepSchedule& schedule);
/// Its restore, after the state's.
/// @throw modeflow::Error as SubstepSchedule::restore, ModalStepper::setHeldRate and setWarmStart.
void restoreCarry(const StepCarry& carry, ModalStepper& stepper, SubstepSchedule& schedule);

}  // namespace modeflow::device
