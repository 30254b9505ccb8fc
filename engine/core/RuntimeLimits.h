#pragma once
/// @file RuntimeLimits.h
/// How many moving parts one simulation takes. The scene loader refuses more at load, the
/// runtime again when it is handed them.

namespace modeflow {

/// The most emitters one scene takes. The device holds emitters as per-cell rates, so the
/// limit is one of scene sanity, not of a buffer.
inline constexpr int maxSmokeEmitters = 64;

/// The most obstacles one scene takes (each step every DOF face's centre is tested against every
/// obstacle in turn).
inline constexpr int maxObstacles = 64;

/// The most `[[inflow]]` patches one scene takes (they share the box's sides).
inline constexpr int maxInflows = 16;

/// The most regions the velocity correction holds at once: every obstacle, every source and
/// every inflow that drives the air (`velocity`).
inline constexpr int maxVelocityRegions = maxObstacles + maxSmokeEmitters + maxInflows;

/// The most `[[particles]]` sets one scene takes.
inline constexpr int maxParticleSets = 64;

/// The most particles one run emits in all (2^24): every one lives on until the run ends, 32 bytes
/// each on the device, and float32 positions still tell them apart.
inline constexpr long long maxParticles = 1LL << 24;

}  // namespace modeflow
