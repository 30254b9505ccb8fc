#pragma once
/// @file DirichletScalarDec.h
/// Ghost-fluid operators for Dirichlet scalars (precompute/README.md). Cut primal stars alone give
/// the Neumann spectrum; a zero value on a curved wall needs the wall's position along each dual
/// edge (Gibou et al. 2002), which converges at second order.

#include "precompute/dec/CutCellDec.h"
#include "precompute/geometry/Domain.h"

namespace modeflow {

struct DirichletScalarDec {
    GridSpec grid;
    DofMap cells;                     ///< cells whose centre is inside Ω
    std::vector<std::int64_t> faces;  ///< faces beside at least one such cell (complex numbering)
    SparseMatrix div;                 ///< d_{n-1} restricted: cells × faces
    Eigen::VectorXd cellStar;         ///< 1 / |cell| (uncut: the unknowns are cell-centre samples)
    /// Face weight |face| / (θ |dual edge|), θ the fraction of the dual edge (centre to
    /// neighbouring centre) inside Ω before the wall; θ = 1 between two inside cells.
    Eigen::VectorXd faceWeight;
};

/// The grid box counts as a wall at its faces (θ = 1/2 there), except along periodic axes. With the
/// staircase treatment every wall sits on the voxel faces (θ = 1/2 everywhere), for comparison.
DirichletScalarDec buildDirichletScalarDec(const CubicalComplex& complex, const Domain& domain,
                                           BoundaryTreatment treatment);

}  // namespace modeflow
