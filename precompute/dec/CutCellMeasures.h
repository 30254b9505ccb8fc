#pragma once
/// @file CutCellMeasures.h
/// The part of every primal element (vertex, edge, face, cell) that lies inside Ω
/// (precompute/README.md, seed §6.3.4): the only geometric input of the cut-cell Hodge stars.

#include <array>
#include <vector>

#include "precompute/dec/CubicalComplex.h"
#include "precompute/geometry/Domain.h"

namespace modeflow {

/// Fractions in [0, 1] per k-cell, in CubicalComplex numbering. A fraction is either exactly 0
/// (the element is not a degree of freedom) or at least `kMinFraction`.
struct CutCellMeasures {
    std::array<std::vector<double>, 4> fraction;
    /// Per face ((n-1)-cell), the fraction inside Ω of the faces lying on the grid box's sides
    /// along their normal (non-periodic axes), measured as the faces inside are; 0 elsewhere.
    /// The sides are walls, so `fraction` holds 0 there; this is what a wind crosses.
    std::vector<double> sideFraction;

    /// Positive fractions are clamped from below: they enter the curl term inverted.
    static constexpr double kMinFraction = 1e-4;
};

/// Measures every element of the complex.
///
/// Cut cells: each element is split into `subsamples`^k sub-boxes, each into k! Kuhn simplices,
/// and the part where the piecewise-linear interpolant of χ is positive is measured exactly, so the
/// result is exact for piecewise-linear χ and second-order accurate for smooth walls. The Kuhn
/// (Freudenthal) triangulation is shared by neighbouring elements, so a face with positive area
/// always has both cells beside it inside. Elements far from the wall (|χ(centre)| above their
/// circumradius) are decided without sampling.
///
/// Staircase: a cell is inside when χ at its centre is; any other element is inside when all the
/// cells around it are (Ω is then the open union of the inside voxels).
///
/// χ at or below a tolerance of 1e-10 h counts as outside, so walls lying on grid planes give
/// exactly zero measures (no round-off "phantom" elements). Elements in the grid box's boundary
/// always measure 0: the box is a wall, except along periodic axes, where χ is evaluated where
/// each element lies (positions 0 … n − 1, the last ones reaching bounds_max).
/// @throw Error naming [[domain]] when the domain does not repeat across a periodic axis's seam
///        (PeriodicSeams.h).
CutCellMeasures measureCutCells(const CubicalComplex& complex, const Domain& domain,
                                BoundaryTreatment treatment, int subsamples);

/// The χ value below which a point counts as outside (see measureCutCells).
double insideTolerance(const GridSpec& grid);

/// Position of a point of an element's sub-lattice: origin + (pos*subsamples + sub) * h/subsamples.
/// Neighbouring elements evaluate shared points bit-identically.
Vec3 subLatticePoint(const GridSpec& grid, const Index3& pos, const Index3& sub, int subsamples);

}  // namespace modeflow
