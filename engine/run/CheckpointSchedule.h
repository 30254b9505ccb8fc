#pragma once
/// @file CheckpointSchedule.h
/// Which frames of `modeflow run` write a checkpoint (`--checkpoint-every K`): every K-th and the
/// last; or, with no K, as often as keeps their writing under 5% of the run's wall time: a
/// checkpoint that took c seconds is followed by the next once 20 c seconds of the run have
/// passed, so a fast checkpoint is written every frame and a slow one (large smoke grids, slow
/// disks) every few. A resumed run restarts after the last checkpoint and writes the frames after
/// it again, to the bit (the run's state is the checkpoint's), so the schedule changes what a
/// kill costs, never what the frames hold.

#include <optional>

namespace modeflow {

class CheckpointSchedule {
public:
    /// `every`: K ≥ 1, or empty for the automatic schedule; `lastFrame`: the run's last frame,
    /// which always writes one (a finished run resumes to nothing).
    /// @throw modeflow::Error when K < 1.
    CheckpointSchedule(std::optional<int> every, int lastFrame);

    /// Whether frame `frame` writes a checkpoint, `now` seconds into the run (any steady clock).
    bool due(int frame, double now);
    /// The last checkpoint took `seconds` to write (0 when none was written).
    void written(double seconds);

    /// The automatic schedule writes a checkpoint once this many times its cost has passed.
    static constexpr double kCostMultiple = 20.0;

private:
    std::optional<int> mEvery;
    int mLastFrame;
    double mLastStart = 0.0;  ///< when the last checkpoint was due
    double mLastCost = 0.0;   ///< what it took to write, in seconds
    bool mAny = false;        ///< one is written (the automatic schedule's first is due at once)
};

}  // namespace modeflow
