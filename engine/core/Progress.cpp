#include "engine/core/Progress.h"

#include <cstdio>
#include <iomanip>
#include <iostream>

#include <unistd.h>

namespace modeflow {

Progress Progress::toStderr() {
    return Progress(&std::cerr, ::isatty(STDERR_FILENO) != 0);
}

void Progress::begin(std::string stage) {
    mStage = std::move(stage);
    mStart = std::chrono::steady_clock::now();
    if (mOut && mLive) *mOut << "\r\033[K" << mStage << " ..." << std::flush;
}

void Progress::update(const std::string& detail) {
    if (!mOut || !mLive) return;
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    *mOut << "\r\033[K" << mStage << " ... " << detail << " (" << std::fixed << std::setprecision(1)
          << t << " s)" << std::flush;
}

void Progress::note(const std::string& message) {
    if (!mOut) return;
    if (mLive) *mOut << "\r\033[K";
    *mOut << message << "\n" << std::flush;
}

double Progress::end() {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    if (mOut) {
        if (mLive) *mOut << "\r\033[K";
        *mOut << mStage << ": " << std::fixed << std::setprecision(2) << t << " s\n" << std::flush;
    }
    return t;
}

}  // namespace modeflow
