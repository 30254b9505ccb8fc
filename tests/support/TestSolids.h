#pragma once
/// @file TestSolids.h
/// Solids' level sets built in code, for the tests of mesh obstacles that need no mesh file.

#include <memory>

#include "engine/simulation/SolidLevelSet.h"

namespace modeflow::testing {

/// A lattice of an L-shaped solid's depth (positive inside; the two boxes' union, the larger of
/// their signed distances: exact inside and at the surface, a lower bound outside), centred near
/// its frame's origin, 0.5 × 0.46 × 0.16 across.
std::shared_ptr<const SolidLevelSet> lShapedLattice();

}  // namespace modeflow::testing
