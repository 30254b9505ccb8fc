#pragma once
/// @file FrameProgress.h
/// Progress of `modeflow run` on stderr: a bar redrawn in place on a terminal (frame, steps/s,
/// ETA), one plain line per frame otherwise (logs, CI), and at the end where a frame's time went
/// (simulating, reading the fields back, writing files), so that a slow run says what is slow.

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace modeflow {

class FrameProgress {
public:
    /// Frames `firstFrame`+1 … `lastFrame` are to come; `stepsPerFrame` converts to steps/s.
    FrameProgress(int firstFrame, int lastFrame, int stepsPerFrame);

    /// Frame `frame` is written; `detail` (e.g. the device's stage times) is added to plain lines.
    void frameDone(int frame, double time, const std::string& detail = {});
    /// Runs `work` and adds its wall time to `stage`'s total (stages print in first-use order).
    /// From any thread (FrameWriter times the files it writes beside the simulation).
    template <typename Work>
    decltype(auto) timed(const char* stage, Work&& work) {
        const auto start = std::chrono::steady_clock::now();
        if constexpr (std::is_void_v<decltype(work())>) {
            work();
            addTime(stage, start);
        } else {
            auto result = work();
            addTime(stage, start);
            return result;
        }
    }
    /// Ends the bar's line and prints the stages' mean wall time per frame.
    void finish();

private:
    void addTime(const char* stage, std::chrono::steady_clock::time_point start);

    std::mutex mStagesMutex;  ///< over mStageSeconds
    std::vector<std::pair<std::string, double>> mStageSeconds;
    int mFirst, mLast, mStepsPerFrame;
    bool mTerminal;
    std::chrono::steady_clock::time_point mStart = std::chrono::steady_clock::now();
};

}  // namespace modeflow
