#pragma once
/// @file ThreadCount.h
/// Scoped OpenMP team size for the calling thread, which both the contractions and Eigen follow.
/// The setting is an OpenMP per-thread value, so other threads are not affected.

#include <omp.h>

namespace modeflow {

class ThreadCount {
public:
    /// threads > 0 sets the team size until the end of the scope; 0 leaves it alone.
    explicit ThreadCount(int threads) : mSaved(omp_get_max_threads()), mSet(threads > 0) {
        if (mSet) omp_set_num_threads(threads);
    }
    ~ThreadCount() {
        if (mSet) omp_set_num_threads(mSaved);
    }
    ThreadCount(const ThreadCount&) = delete;
    ThreadCount& operator=(const ThreadCount&) = delete;

private:
    int mSaved;
    bool mSet;
};

}  // namespace modeflow
