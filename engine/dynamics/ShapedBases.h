#pragma once
/// @file ShapedBases.h
/// The shaped bases a cache holds (seed §6.4, frequency shaping): a scene whose basis lists
/// several mode ranges, e.g. `modes = "1-10,391-400"`, can also run on the leading ranges
/// alone ("1-10"), because the cache stores its modes range by range. `modeflow stir` switches
/// between them to compare a low basis with the same basis plus high modes.

#include <memory>
#include <string>
#include <vector>

#include "engine/core/SceneSpec.h"
#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

struct ShapedBasis {
    std::string label;  ///< the ranges it keeps, e.g. "1-10,391-400"
    int modes = 0;      ///< the cache's leading columns it keeps
};

/// The scene's bases from the first range alone up to all of them (one entry when the basis
/// has a single range).
std::vector<ShapedBasis> shapedBases(const BasisSpec& basis);

/// The cache restricted to its first `modes` velocity modes (the scalar basis is kept whole).
/// @throw modeflow::Error when `modes` is not between 1 and the cache's count.
BasisCache leadingModes(const BasisCache& cache, int modes);
/// C[k][i][j] over k, i, j < modes (the Galerkin system of the leading modes).
std::unique_ptr<StructuralCoefficients> leadingCoefficients(
    const StructuralCoefficients& coefficients, int modes);

}  // namespace modeflow
