#pragma once
/// @file WholeBoxDofs.h
/// The degrees of freedom of a whole grid box and their Hodge stars, as buildCutCellDec gives
/// them there, without measuring anything: every cell (⋆n = 1/|cell|), every face not on a wall
/// (⋆(n−1) = h_a / |face|). On a periodic axis the face at position 0 stands for its plane.

#include "engine/format/BasisCache.h"

namespace modeflow {

/// Fills cache.cellFraction (all 1), faces, faceStar, cells and cellStar for cache.grid.
void fillWholeBoxDofs(BasisCache& cache);

}  // namespace modeflow
