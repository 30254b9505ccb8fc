#pragma once
/// @file PeakMemory.h
/// The test process's peak resident memory, for tests that pin that a reader refuses a large
/// file without reading it whole.

#include <sys/resource.h>

namespace modeflow::testing {

/// The process's peak resident memory so far, in MiB.
inline long peakMemoryMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;  // kilobytes on Linux
}

}  // namespace modeflow::testing
