#pragma once
/// @file RuntimeLimits.h
/// How many moving parts one simulation takes: the device kernels hold them in fixed buffers.
/// The scene loader refuses more at load, the runtime again when it is handed them.

namespace modeflow {

/// The most emitters one device step takes (the kernels' emitter buffer).
inline constexpr int maxSmokeEmitters = 8;

/// The most obstacles one scene takes (the device kernel's obstacle buffer).
inline constexpr int maxObstacles = 8;

}  // namespace modeflow
