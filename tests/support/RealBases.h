#pragma once
/// @file RealBases.h
/// Real cut-cell bases (divergence-free, free-slip, realistic boundaries) for the tests, shared
/// by the test processes of one CTest run, and the contract every velocity basis meets. Runs set
/// up on them: SharedRuns.h. Synthetic bases (any size, quick): SyntheticBases.h.

#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow::testing {

/// The scene's basis. Under CTest, from the folder MODEFLOW_TEST_BASES names, computed and
/// written there by the first test that needs it (the folder is emptied when a run starts, see
/// tests/CMakeLists.txt: CTest runs every test case in a process of its own, and most would
/// otherwise compute the same bases again); computed in memory when the variable is unset.
BasisCache sharedBasis(const SceneSpec& scene);

/// The unit disk at 32² with 20 velocity modes and the unit ball at 12³ with 10 (no scalar
/// modes), once per process.
const BasisCache& disk2d();
const BasisCache& ball3d();
/// The unit disk at 40² with 100 velocity modes (no scalar modes) and their dense coefficients,
/// once per process.
const BasisCache& disk2dHundredModes();

/// Periodic bases, once per process: TestScenes' channel around a disk at 32 × 16 cells,
/// periodic along x (periodicChannel2d) and along both axes, a torus around a disk, whose up
/// axis wraps too (torusAroundDisk2d), 20 velocity modes each; the whole 3D torus [−1, 1]³ at 8³
/// with 12 (torus3d). No scalar modes.
const BasisCache& periodicChannel2d();
const BasisCache& torusAroundDisk2d();
const BasisCache& torus3d();

/// The contract every velocity basis meets: max |dΨ|/|Ψ| and |ΨᵀMΨ − I| ≤ 1e-10, recomputed
/// from the stored data (precompute/BasisChecks).
void expectValidVelocityBasis(const BasisCache& cache);

}  // namespace modeflow::testing
