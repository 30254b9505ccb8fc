#include "engine/stir/StirStatistics.h"

#include <cstdio>

namespace modeflow::stir {

void StirStatistics::StageTimes::add(const FrameStats& s) {
    steps += s.timedSteps;
    forces += s.forcesMs;
    modal += s.modalMs;
    reconstruction += s.reconstructionMs;
    obstacles += s.obstaclesMs;
    advection += s.advectionMs;
}

std::string StirStatistics::StageTimes::line() const {
    if (steps == 0) return "gpu ms per step: -";
    char text[160];
    std::snprintf(text, sizeof text,
                  "gpu ms per step: forces %.1f  modal %.1f  velocity %.1f  smoke %.1f",
                  forces / steps, modal / steps, reconstruction / steps, advection / steps);
    std::string line = text;
    if (obstacles > 0.0) {
        std::snprintf(text, sizeof text, "  obstacles %.1f", obstacles / steps);
        line += text;
    }
    return line;
}

void StirStatistics::addSteps(int steps, double wallSeconds, const FrameStats& stats) {
    mStages.add(stats);
    if (steps <= 0) return;
    mSteps += steps;
    mStepWall += wallSeconds;
    const double perStep = wallSeconds / steps;
    mStepSeconds = mStepSeconds > 0.0 ? 0.8 * mStepSeconds + 0.2 * perStep : perStep;
}

void StirStatistics::countFrame(double energy, double time, const std::string& status,
                                const std::string& state) {
    ++mSampleFrames;
    const double sampled = std::chrono::duration<double>(Clock::now() - mSampleStart).count();
    if (sampled < 0.25 && !mText.empty()) return;
    char line[256];
    std::snprintf(line, sizeof line, "%s   %.1f fps   step %.1f ms   energy %.4g   t %.2f s   %s",
                  mSceneName.c_str(), sampled > 0.0 ? mSampleFrames / sampled : 0.0,
                  1e3 * mStepSeconds, energy, time, state.c_str());
    mText = std::string(line) + "\n" + (mStageTimes ? mStages.line() + "\n" : "") + status +
            "\nh: help";
    mStages = {};
    mSampleFrames = 0;
    mSampleStart = Clock::now();
}

void StirStatistics::addPicture(double wallSeconds) {
    mPictureWall += wallSeconds;
    ++mPictures;
}

}  // namespace modeflow::stir
