#include "engine/run/FrameProgress.h"

#include <unistd.h>

namespace modeflow {
namespace {

std::string duration(double seconds) {
    const long s = long(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

}  // namespace

FrameProgress::FrameProgress(int firstFrame, int lastFrame, int stepsPerFrame)
    : mFirst(firstFrame),
      mLast(lastFrame),
      mStepsPerFrame(stepsPerFrame),
      mTerminal(::isatty(STDERR_FILENO) != 0) {}

void FrameProgress::frameDone(int frame, double time, const std::string& detail) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    const int done = frame - mFirst, total = mLast - mFirst;
    const double stepsPerSecond = elapsed > 0.0 ? done * mStepsPerFrame / elapsed : 0.0;
    const double eta = done > 0 ? elapsed / done * (mLast - frame) : 0.0;
    if (mTerminal) {
        constexpr int width = 30;
        const int filled = total > 0 ? width * done / total : width;
        std::string bar(std::size_t(filled), '#');
        bar.resize(width, '.');
        std::fprintf(stderr, "\rframe %d/%d [%s] %.1f steps/s, ETA %s   ", frame, mLast,
                     bar.c_str(), stepsPerSecond, duration(eta).c_str());
    } else {
        std::fprintf(stderr, "frame %d/%d  t=%.4g  %.1f steps/s  ETA %s%s%s\n", frame, mLast, time,
                     stepsPerSecond, duration(eta).c_str(), detail.empty() ? "" : "  ",
                     detail.c_str());
    }
    std::fflush(stderr);
}

void FrameProgress::addTime(const char* stage, std::chrono::steady_clock::time_point start) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::lock_guard lock(mStagesMutex);
    for (auto& [name, total] : mStageSeconds)
        if (name == stage) {
            total += seconds;
            return;
        }
    mStageSeconds.emplace_back(stage, seconds);
}

void FrameProgress::finish() {
    if (mTerminal) std::fprintf(stderr, "\n");
    const int frames = mLast - mFirst;
    const std::lock_guard lock(mStagesMutex);
    if (frames <= 0 || mStageSeconds.empty()) return;
    std::string line = "per frame:";
    const char* separator = "";
    for (const auto& [name, total] : mStageSeconds) {
        char part[128];
        std::snprintf(part, sizeof part, "%s %s %.1f ms", separator, name.c_str(),
                      1e3 * total / frames);
        line += part;
        separator = ",";
    }
    std::fprintf(stderr, "%s\n", line.c_str());
}

}  // namespace modeflow
