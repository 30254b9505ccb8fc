#pragma once
/// @file SyntheticBases.h
/// Synthetic bases for the kernel tests and tools/bench: random ⋆-orthonormal modes on every
/// interior face of a box grid, any size, quick to make. Not divergence-free and no eigenbasis:
/// what a stage does and how fast does not depend on that. Real cut-cell bases: RealBases.h.

#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow::testing {

/// A grid over a non-cubic box ([−1, 1.2] × [−0.9, 1] (× [−0.8, 1.3])), so axis mix-ups show.
GridSpec boxGrid(int dim, int cells);

/// A complete cache on `grid`: `modes` random modes on every face not on a wall of the box (the
/// seam's faces of a periodic axis included), each face with
/// a random cut fraction in [0.3, 1] (⋆ = h / (area × fraction), as for a cut face),
/// ⋆-orthonormalized; κ² = 1 … modes; every cell fluid; random dense coefficients (randomDense).
/// prepareRun takes it as a real basis.
BasisCache syntheticBasis(const GridSpec& grid, int modes, unsigned seed);

/// The same without coefficients (storage None, no quadrature): the modes of a size whose full
/// random tensor would not fit.
BasisCache syntheticModes(const GridSpec& grid, int modes, unsigned seed);

}  // namespace modeflow::testing
