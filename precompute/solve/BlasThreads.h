#pragma once
/// @file BlasThreads.h
/// How many threads OpenBLAS's calls use, set for a scope. Solves that run at once on several
/// cores each want one BLAS thread: OpenBLAS's own threads would share the same cores with them
/// (on the seed's sphere scene, two concurrent CHOLMOD solves with two BLAS threads each took
/// twice as long as one solve after the other).
///
/// Debian's BLAS alternative (libblas.so.3) exports the BLAS routines only, so OpenBLAS's
/// openblas_set_num_threads is looked up at run time in what the process loaded; with another
/// BLAS selected there is none, controllable() is false, and callers keep to one solve at a time.

namespace modeflow {

class BlasThreads {
public:
    /// Whether the BLAS the process uses lets its thread count be set.
    static bool controllable();

    /// Sets the thread count (where controllable()) until the end of the scope.
    explicit BlasThreads(int threads);
    ~BlasThreads();
    BlasThreads(const BlasThreads&) = delete;
    BlasThreads& operator=(const BlasThreads&) = delete;

private:
    int mSaved = 0;
};

}  // namespace modeflow
