#pragma once
/// @file LibraryLeaks.h
/// What libraries allocate and never free, kept out of the leak checker's report in sanitized
/// builds (MODEFLOW_SANITIZE), so that it reports our own leaks only:
///   - Open MPI's start and stop (MPI_Init, MPI_Finalize: about 120 KB in 3000 blocks);
///   - SLEPc 3.18's spectrum slicing when an interval ends inside a cluster of eigenvalues
///     (EPSSolve: 53 KB in 5 blocks, SlicedEigensolverTest.ClusterOnAnIntervalEndFoundOnce);
///   - the Vulkan driver's load (vkEnumeratePhysicalDevices, or vkCreateInstance with the
///     validation layer): lavapipe's LLVM keeps 128 bytes from a one-time initialization, which
///     the leak checker sees as leaked once vkDestroyInstance has unloaded the driver and its
///     LLVM (Mesa 22.3.6-1+deb12u2).
/// Only the calling thread's allocations are ignored: Open MPI's progress thread under mpirun
/// (32 bytes) is suppressed by the sanitized tests' environment instead (tests/CMakeLists.txt).

#if defined(__SANITIZE_ADDRESS__)
#define MODEFLOW_LEAK_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MODEFLOW_LEAK_SANITIZER 1
#endif
#endif
#ifdef MODEFLOW_LEAK_SANITIZER
#include <sanitizer/lsan_interface.h>
#endif

namespace modeflow {

/// While one lives, the calling thread's allocations are not reported as leaks.
struct IgnoreLibraryLeaks {
#ifdef MODEFLOW_LEAK_SANITIZER
    __lsan::ScopedDisabler disabler;
#endif
};

}  // namespace modeflow
