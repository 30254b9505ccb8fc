#pragma once
/// @file AvailableMemory.h
/// How much memory this machine can still give, the one refusal used when an estimate says a
/// command would not fit (the precompute's, precompute/PrecomputeMemory.h, and the run's,
/// engine/simulation/RunMemory.h), and the one message for an allocation that failed anyway.

#include <cstdint>
#include <optional>
#include <string>

#include "engine/core/Error.h"

namespace modeflow {

/// Bytes available: MODEFLOW_MEMORY_LIMIT (a whole number of bytes) when set, else MemAvailable
/// of /proc/meminfo; none when neither can be read.
/// @throw modeflow::Error for a MODEFLOW_MEMORY_LIMIT that is not a positive whole number.
std::optional<std::uint64_t> availableMemory();

/// "4.37 GiB", "512 MiB", "13.7 TiB".
std::string memoryText(double bytes);

/// @throw modeflow::Error "<subject>: <what> needs about X (estimate), but only Y are available
/// (<source>); <advice>" when `estimateBytes` exceeds availableMemory(); nothing when it fits or
/// nothing is known.
void requireMemory(double estimateBytes, const std::string& subject, const std::string& what,
                   const std::string& advice);

/// The error for a std::bad_alloc caught at a stage boundary despite the estimate: "out of memory
/// in <stage> (the estimated peak was X); <advice>".
Error outOfMemoryIn(const std::string& stage, double estimateBytes, const std::string& advice);

}  // namespace modeflow
