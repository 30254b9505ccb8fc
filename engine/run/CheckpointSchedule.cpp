#include "engine/run/CheckpointSchedule.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {

CheckpointSchedule::CheckpointSchedule(std::optional<int> every, int lastFrame)
    : mEvery(every), mLastFrame(lastFrame) {
    if (mEvery && *mEvery < 1)
        throw Error("--checkpoint-every " + std::to_string(*mEvery) + ": at least 1 frame");
}

bool CheckpointSchedule::due(int frame, double now) {
    bool due = frame == mLastFrame;
    if (mEvery)
        due = due || frame % *mEvery == 0;
    else
        due = due || !mAny || now - mLastStart >= kCostMultiple * mLastCost;
    if (due) {
        mLastStart = now;
        mAny = true;
    }
    return due;
}

void CheckpointSchedule::written(double seconds) {
    if (seconds > 0.0) mLastCost = seconds;
}

}  // namespace modeflow
