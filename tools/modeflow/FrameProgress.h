#pragma once
/// @file FrameProgress.h
/// Progress of `modeflow run` on stderr: a bar redrawn in place on a terminal (frame, steps/s,
/// ETA), one plain line per frame otherwise (logs, CI).

#include <chrono>
#include <cstdio>
#include <string>

namespace modeflow::cli {

class FrameProgress {
public:
    /// Frames `firstFrame`+1 … `lastFrame` are to come; `stepsPerFrame` converts to steps/s.
    FrameProgress(int firstFrame, int lastFrame, int stepsPerFrame);

    /// Frame `frame` is written; `detail` (e.g. the device's stage times) is added to plain lines.
    void frameDone(int frame, double time, const std::string& detail = {});
    /// Ends the bar's line.
    void finish();

private:
    int mFirst, mLast, mStepsPerFrame;
    bool mTerminal;
    std::chrono::steady_clock::time_point mStart = std::chrono::steady_clock::now();
};

}  // namespace modeflow::cli
