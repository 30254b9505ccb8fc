#pragma once
/// @file Sanitizers.h
/// Whether the tests are built with AddressSanitizer (MODEFLOW_SANITIZE, `tools/run-tests.sh
/// --sanitize`), for the few tests whose subject it changes: a process's peak memory (its shadow
/// memory, redzones and quarantine) and an allocation that fails (it aborts the process instead
/// of throwing std::bad_alloc).

namespace modeflow::testing {

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define MODEFLOW_ADDRESS_SANITIZER 1
#elif defined(__has_feature)  // Clang
#if __has_feature(address_sanitizer)
#define MODEFLOW_ADDRESS_SANITIZER 1
#endif
#endif

#ifdef MODEFLOW_ADDRESS_SANITIZER
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace modeflow::testing
