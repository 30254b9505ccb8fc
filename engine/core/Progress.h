#pragma once
/// @file Progress.h
/// Stage reports of a long precompute. On a terminal a live counter rewrites one line; otherwise
/// (logs, CI, tests) only one plain line per finished stage is written.

#include <chrono>
#include <iosfwd>
#include <string>

namespace modeflow {

class Progress {
public:
    /// `out` null: silent. `live`: rewrite the current line with counters (a terminal).
    Progress(std::ostream* out, bool live) : mOut(out), mLive(live) {}
    /// Reports to stderr, live when stderr is a terminal.
    static Progress toStderr();
    static Progress silent() { return Progress(nullptr, false); }

    void begin(std::string stage);
    /// A counter inside the current stage (e.g. solves done); shown only when live.
    void update(const std::string& detail);
    /// A message of its own line (a warning, a decision taken).
    void note(const std::string& message);
    /// Ends the current stage and returns its duration in seconds.
    double end();
    /// The stage begun last (named in errors, e.g. "out of memory in velocity eigensolve").
    const std::string& stage() const { return mStage; }

private:
    std::ostream* mOut;
    bool mLive;
    std::string mStage;
    std::chrono::steady_clock::time_point mStart;
};

}  // namespace modeflow
