#pragma once
/// @file EigenMethod.h
/// Which method finds a problem's lowest eigenpairs (SpectralBasis.h's lowestEigenpairs), and
/// the precompute's memory estimate (precompute/PrecomputeMemory.h), chosen from the scene's
/// `eigensolver`, the problem's size, the count and the MPI ranks.

#include <cstdint>

#include "engine/core/SceneSpec.h"

namespace modeflow {

enum class EigenMethod {
    Dense,         ///< up to kDenseLimit unknowns: exact for any count
    Lanczos,       ///< shift-invert, a vector at a time (Spectra)
    BlockLanczos,  ///< shift-invert, a block at a time (BlockLanczos.h)
    Slicing        ///< spectrum slicing over MPI ranks, resumable intervals (SLEPc)
};

/// Up to this many unknowns a dense solve is cheaper and exact for any count.
inline constexpr std::int64_t kDenseLimit = 1200;

/// From this many eigenpairs on, Automatic searches in blocks: on the seed's sphere scene
/// (147 k unknowns, 230 eigenpairs) block Lanczos took 65 s where Spectra's Lanczos took
/// 132–138 s. Below four blocks of vectors a block run mostly restarts (the first Neumann
/// eigenvalue alone took 160 solves), where one vector at a time needs a few dozen.
inline constexpr int kBlockLanczosFromCount = 64;

/// From this many eigenpairs on, Automatic slices the spectrum on one process (on several MPI
/// ranks it always does: only slicing shares the work). Below it one factorization and a block
/// search space of twice the count beat slicing's factorization per interval (precompute/
/// README.md, "Whole precomputes by size").
inline constexpr int kSlicingFromCount = 1001;

/// The method for `count` eigenpairs of a problem on `unknowns` unknowns.
EigenMethod chooseEigenMethod(std::int64_t unknowns, std::int64_t count, EigensolverChoice choice,
                              int ranks);

}  // namespace modeflow
