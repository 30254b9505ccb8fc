#pragma once
/// @file CacheConsistency.h
/// What the runtime takes on trust from a cache: the grid, the choices and the sizes and indices
/// of the arrays (a face number indexes straight into a face field). The checksum catches damage;
/// this catches a file that is well-formed but describes no basis a precompute writes.

#include <string>

#include "engine/format/BasisCache.h"

namespace modeflow {

/// @throw Error "<where> is corrupt (<what is inconsistent>)" for a cache whose grid is not 2D or
///        3D with positive sizes, whose choices are out of range, or whose arrays disagree in size
///        or hold indices outside the grid (a surface basis: its mesh) or the basis.
void requireConsistentCache(const BasisCache& cache, const std::string& where);

}  // namespace modeflow
