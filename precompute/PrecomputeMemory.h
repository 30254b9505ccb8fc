#pragma once
/// @file PrecomputeMemory.h
/// The precompute's peak memory, estimated before any work from the grid, the domain and the
/// mode counts, so that a scene the machine cannot hold is refused at once rather than ending
/// in "out of memory" minutes later.
///
/// The model, per stage (bytes; V velocity DOFs = faces of Ω, S scalar DOFs = cells of Ω, C grid
/// cells, N the highest velocity mode, K the modes kept, M the scalar modes):
///   measures      430·C (3D) or 280·C (2D), transient
///   resident      310·C + 490·V (3D) or 50·C + 300·V (2D): grid, measures, operators
///   eigensolve    n·(ncv + 2·count)·8 (Krylov basis, Ritz vectors, their rescaled copy; ncv =
///                 max(1.5·count + 1, count + 30); slicing alike), or for block Lanczos
///                 n·(count + max(count, 64) + 48 + count)·8 (search space, working blocks, Ritz
///                 vectors; precompute/solve/EigenMethod.h says which)
///                 + 13·nnz(L) (CHOLMOD's peak) + 24·nnz(K) (operator and its shifted copy),
///                 nnz(L) ≈ 11·n^{4/3} (3D) or 4·n·log2(n) (2D) for the velocity operator,
///                 5.5·n^{4/3} or 2·n·log2(n) for the scalar one; up to 1200 unknowns 3·n²·8
///                 (dense)
///   coefficients  2·V·K·8 (modes) + 1.6·K²(K−1)/2·8 (packed, sparse copy) + (V/dim)·(3K+256)·8
///                 + 2·120·V (the vorticity quadrature and its copy); without a tensor
///                 (precompute/CoefficientChoice.h) the packed and element terms are 0
///   cache write   3 × the cache (serialized into a growing string)
/// plus the scalar modes (3 copies of S·M·8) and 40 MiB for the program itself, the largest
/// stage times 1.15. A closed-form precompute (whole box, free slip) solves and measures nothing:
/// its peak is the DOF arrays and the sparse coefficients, 20 bytes per estimated non-zero
/// (estimatedClosedFormNonZeros), assembled in place and streamed to the cache. Against measured
/// peaks (VmHWM; 2D disks 128²–512² with 50–200 modes, 3D balls 32³–64³ with 100–200 modes, a 32³
/// box) the model with the exact DOF counts is 0.92–1.17 of the peak; the estimate, with sampled
/// DOF counts and the margin, 1.07–1.40.

#include <cstdint>
#include <string>

#include "engine/core/SceneSpec.h"

namespace modeflow {

struct PrecomputeMemory {
    std::int64_t velocityDofs = 0;  ///< estimated faces of Ω
    std::int64_t scalarDofs = 0;    ///< estimated cells of Ω
    double peakBytes = 0.0;         ///< the largest stage
    std::string peakStage;
    bool tensor =
        true;  ///< the structural coefficients are assembled (precompute/CoefficientChoice.h)
    /// The peak with one velocity mode and no scalar modes: what only a coarser grid can lower.
    double gridBytes = 0.0;
};

/// The estimate. The scalar DOFs are the grid cells reaching into Ω, sampled on a lattice of at
/// most 64 points per axis; the velocity DOFs are dim per such cell.
/// @throw Error when a domain shape cannot be built.
PrecomputeMemory estimatePrecomputeMemory(const SceneSpec& scene);

/// "[grid].resolution = [64, 64, 64]", for messages.
std::string gridResolutionText(const GridSpec& grid);

/// The estimate, when it fits in the available memory (engine/core/AvailableMemory.h).
/// @throw Error naming [grid].resolution (and the mode counts when fewer would fit), the
/// estimate and the available memory, when it does not.
PrecomputeMemory requirePrecomputeMemory(const SceneSpec& scene);

}  // namespace modeflow
