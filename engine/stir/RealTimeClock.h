#pragma once
/// @file RealTimeClock.h
/// Keeps `modeflow stir`'s simulation on the wall clock: each frame takes the steps of size dt
/// that the elapsed wall time calls for, as long as they fit in the frame's budget. When they do
/// not (a step costs more than real time allows), it takes what fits and lets the rest go: the
/// simulation then runs in slow motion, and speed() says by how much, rather than falling
/// further behind every frame.

namespace modeflow::stir {

class RealTimeClock {
public:
    /// `dt`: the simulation's step; `budget`: wall seconds a frame may spend on steps.
    RealTimeClock(double dt, double budget) : mDt(dt), mBudget(budget) {}

    /// Steps for this frame, `wallElapsed` seconds after the previous one, when one step
    /// costs `stepSeconds` (0 before any was measured).
    int stepsFor(double wallElapsed, double stepSeconds);
    /// Simulated seconds per wall second, smoothed over about a second (1: real time).
    double speed() const { return mSpeed; }
    bool isSlowMotion() const { return mSpeed < 0.9; }
    /// Forgets the time owed (after a pause).
    void restart() { mOwed = 0.0; }

private:
    double mDt;
    double mBudget;
    double mOwed = 0.0;  ///< wall seconds not yet simulated
    double mSpeed = 1.0;
};

}  // namespace modeflow::stir
