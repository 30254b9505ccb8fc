#pragma once
/// @file ClosedFormBasis.h
/// The eigenbases of a whole grid box (free-slip walls) or torus, or a mix of wall and periodic
/// axes, in closed form (engine/format/SeparableModes.h): the same eigenvalues, multiplicities and
/// eigenspaces as the eigensolver gives on that grid, at the cost of sorting wave vectors.
///
/// Per axis a wall carries l = 0..n−1 (phase 0); a periodic axis l = 0..⌊n/2⌋ in two phases (one
/// at l = n/2, where the other vanishes on the grid). A velocity wave vector carries one field per
/// active component (u_a ≠ 0 on the grid) less one for the divergence condition amplitude ⟂ σ:
/// in 3D two when every l_a ≠ 0, one when one is 0. A periodic axis with l_a = 0 in phase 1 makes
/// u_a the only component (then divergence-free by itself): the uniform flows along periodic axes
/// (harmonic, κ² = 0) and shear flows.

#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/format/SeparableModes.h"

namespace modeflow {

struct ClosedFormVelocity {
    Eigen::VectorXd eigenvalues;  ///< κ² (harmonic: exactly 0)
    std::vector<SeparableMode> modes;
    std::vector<int> modeNumbers;  ///< 1-based positions in the ascending div-free spectrum
    int harmonicCount = 0;
};

struct ClosedFormScalar {
    Eigen::VectorXd eigenvalues;  ///< μ², ascending
    std::vector<SeparableMode> modes;
    int omittedConstants = 0;
};

/// The div-free modes in `ranges` (1-based), in ascending κ²; within equal κ² ordered by wave
/// vector, phases and polarization (a fixed order, so a basis is reproducible).
/// @throw Error when the ranges ask for more modes than the grid holds.
ClosedFormVelocity closedFormVelocityBasis(const GridSpec& grid,
                                           const std::vector<ModeRange>& ranges);

/// The first `count` scalar modes: Neumann without the constant, or Dirichlet with the ghost-fluid
/// wall of the eigensolver (zero half a cell beyond the last cell centre: sin(πl(x)/n), l = 1..n).
/// @throw Error when the grid holds fewer.
ClosedFormScalar closedFormScalarBasis(const GridSpec& grid, int count, ScalarBoundary boundary);

/// Dimension of the div-free space of the grid (the modes a closed-form basis can hold).
std::int64_t closedFormDivergenceFreeDimension(const GridSpec& grid);

}  // namespace modeflow
