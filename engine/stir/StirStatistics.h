#pragma once
/// @file StirStatistics.h
/// What the stir window says about itself: frames per second, the wall time of a step (smoothed;
/// RealTimeClock plans with it), each stage's device time per step where the backend measures
/// it, the energy, and the text lines over the picture made of them, refreshed about four times
/// a second; and the run's totals for its summary line.

#include <chrono>
#include <string>
#include <utility>

#include "engine/simulation/FrameStats.h"

namespace modeflow::stir {

class StirStatistics {
public:
    /// `stageTimes`: whether the backend measures them (BackendCapabilities::stageTimes).
    StirStatistics(std::string sceneName, bool stageTimes)
        : mSceneName(std::move(sceneName)), mStageTimes(stageTimes) {}

    /// Whether the next steps should time their stages: timestamps would double a step's cost
    /// on lavapipe, so one frame's steps are timed per refresh of the text.
    bool timesNextSteps() const { return mStages.steps == 0; }
    /// A frame's `steps` took `wallSeconds`, with the stage times in `stats`.
    void addSteps(int steps, double wallSeconds, const FrameStats& stats);
    /// Wall seconds per step, smoothed over the last few frames (0 before the first step).
    double stepSeconds() const { return mStepSeconds; }

    /// Counts a frame; remakes the text before the first picture and every 0.25 s after it, of
    /// the scene's ½|v|², simulated time and status line (StirScene.h) and `state`: PAUSED,
    /// SLOW MOTION ×…, or empty.
    void countFrame(double energy, double time, const std::string& status,
                    const std::string& state);
    /// The lines over the picture: scene, frame rate, step time, energy, time and state; the
    /// stage times (where measured); the session's status; the help key.
    const std::string& text() const { return mText; }

    /// A picture drawn and shown in `wallSeconds`.
    void addPicture(double wallSeconds);
    int steps() const { return mSteps; }
    int pictures() const { return mPictures; }
    /// Mean wall milliseconds per step and per picture over the run.
    double stepMs() const { return mSteps > 0 ? 1e3 * mStepWall / mSteps : 0.0; }
    double pictureMs() const { return mPictures > 0 ? 1e3 * mPictureWall / mPictures : 0.0; }

private:
    using Clock = std::chrono::steady_clock;

    /// Device time per stage, summed over the timed steps since the last refresh.
    struct StageTimes {
        int steps = 0;
        double forces = 0.0, modal = 0.0, reconstruction = 0.0, obstacles = 0.0, advection = 0.0;
        void add(const FrameStats& s);
        /// Milliseconds per step, one line.
        std::string line() const;
    };

    std::string mSceneName;
    bool mStageTimes;
    std::string mText;
    double mStepSeconds = 0.0;
    StageTimes mStages;
    int mSampleFrames = 0;
    Clock::time_point mSampleStart = Clock::now();
    int mSteps = 0, mPictures = 0;
    double mStepWall = 0.0, mPictureWall = 0.0;
};

}  // namespace modeflow::stir
