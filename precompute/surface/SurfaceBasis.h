#pragma once
/// @file SurfaceBasis.h
/// The velocity and scalar bases of a closed surface (precompute/README.md, "Surfaces").
///
/// Scalars are the Laplace–Beltrami eigenfunctions, L ψ = λ ⋆0 ψ with L = d0ᵀ⋆1d0, without
/// the constants (one per connected component), ⋆0-orthonormal. The divergence-free velocity
/// space of a closed surface is the co-exact fields plus the harmonic ones:
///   co-exact  Ψ = d0 ψ / √λ for each of those eigenfunctions (the stream-function route): the
///             Hodge Laplacian ⋆1d0⋆0⁻¹d0ᵀ⋆1 + d1ᵀ⋆2d1 maps it to λ ⋆1 Ψ, so κ² = λ, and
///             Ψᵀ⋆1Ψ = ψᵀLψ/λ = 1;
///   harmonic  the 2g fields of a genus-g surface (κ = 0), one per non-contractible dual loop of
///             a tree–cotree decomposition, made harmonic (h = c − d0ψ with Lψ = d0ᵀ⋆1c) and
///             ⋆1-orthonormalized.
/// Both are exactly divergence-free: d1d0 = 0 and d1 c = 0 hold in integers.

#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "precompute/solve/ShiftInvertEigensolver.h"
#include "precompute/surface/SurfaceDec.h"

namespace modeflow {

struct SurfaceBasisResult {
    Eigen::VectorXd velocityEigenvalues;  ///< κ², harmonic first (exactly 0), then ascending
    Eigen::MatrixXd velocityModes;        ///< edge fluxes × modes, ⋆1-orthonormal
    std::vector<int> modeNumbers;         ///< 1-based position in the divergence-free spectrum
    int harmonicCount = 0;                ///< selected modes with κ = 0
    Eigen::VectorXd scalarEigenvalues;    ///< λ, ascending
    Eigen::MatrixXd scalarModes;          ///< vertex values × modes, ⋆0-orthonormal
    int omittedConstants = 0;             ///< one per connected component
    SolverStats stats;
};

/// The surface's harmonic 1-forms (edges × β1), ⋆1-orthonormal, d1 h = 0 exactly.
Eigen::MatrixXd harmonicForms(const SurfaceDec& dec);

/// The velocity modes in `ranges` (1-based, of the divergence-free spectrum, harmonic ones
/// first) and the first `scalarModes` non-constant scalar modes.
/// @throw Error naming [basis] when the ranges or the scalar count ask for more modes than
///        the surface holds, or the eigensolve's error.
SurfaceBasisResult solveSurfaceBasis(const SurfaceDec& dec, const std::vector<ModeRange>& ranges,
                                     int scalarModes, const SolveProgress& progress);

}  // namespace modeflow
