#include "engine/stir/RealTimeClock.h"

#include <algorithm>
#include <cmath>

namespace modeflow::stir {

int RealTimeClock::stepsFor(double wallElapsed, double stepSeconds) {
    mOwed += std::max(wallElapsed, 0.0);
    const int wanted = int(std::floor(mOwed / mDt));
    const int affordable = stepSeconds > 0.0 ? std::max(1, int(mBudget / stepSeconds)) : 1;
    const int steps = std::min(wanted, affordable);
    // Time the budget cannot pay for is dropped, not owed: owing it would make every later
    // frame try to catch up and fall further behind.
    mOwed = wanted > affordable ? 0.0 : mOwed - steps * mDt;
    if (wallElapsed > 0.0) {
        const double weight = std::min(1.0, wallElapsed);  // about a second of memory
        const double now = wanted > affordable ? steps * mDt / wallElapsed : 1.0;
        mSpeed += weight * (now - mSpeed);
    }
    return steps;
}

}  // namespace modeflow::stir
