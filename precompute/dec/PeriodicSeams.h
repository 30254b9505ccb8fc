#pragma once
/// @file PeriodicSeams.h
/// The seams of periodic axes, where the plane at bounds_max is the plane at bounds_min. The
/// domain's χ is made of ordinary shapes, so it repeats across a seam only where the scene makes
/// it so (a shape that reaches past both ends, or none near them); a domain that does not would
/// give the basis of some other domain, so these checks refuse it, naming [[domain]].

#include "precompute/dec/CutCellMeasures.h"

namespace modeflow {

/// χ sampled on every sub-lattice point of each seam (the points the measures use) at both ends
/// of the periodic axis.
/// @throw Error naming [[domain]] and a point where one end is inside Ω and the other outside.
void requireDomainAgreesAcrossSeams(const CubicalComplex& complex, const Domain& domain,
                                    int subsamples);

/// A face on a seam with no measure between two whole cells is a wall lying in the seam plane
/// (e.g. a box domain that ends at the grid box along a periodic axis): it would close the axis.
/// @throw Error naming [[domain]] and the axis when there is one.
void requireNoWallOnSeams(const CubicalComplex& complex, const CutCellMeasures& measures);

}  // namespace modeflow
