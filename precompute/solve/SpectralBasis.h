#pragma once
/// @file SpectralBasis.h
/// The velocity and scalar eigenbases of a domain (seed §6.3.1, appendix C.1;
/// precompute/README.md).

#include <vector>

#include <Eigen/Core>

#include "precompute/dec/CutCellDec.h"
#include "precompute/dec/DirichletScalarDec.h"
#include "precompute/solve/EigenMethod.h"
#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {

struct VelocityBasisResult {
    Eigen::VectorXd eigenvalues;  ///< κ², ascending, one per selected mode (harmonic: 0)
    /// Face fluxes (DOFs × modes), ⋆(n-1)-orthonormal; each mode's first entry of largest
    /// magnitude is positive, so that its sign does not depend on the solver or the machine.
    Eigen::MatrixXd modes;
    std::vector<int> modeNumbers;  ///< 1-based position of each mode in the div-free spectrum
    int harmonicCount = 0;         ///< selected modes with κ = 0
    double penalty = 0.0;          ///< grad-div penalty s that kept gradients out
    SolverStats stats;
};

struct ScalarBasisResult {
    Eigen::VectorXd eigenvalues;  ///< μ², ascending
    Eigen::MatrixXd modes;        ///< cell values (n-forms), ⋆n-orthonormal, signed as above
    int omittedConstants = 0;     ///< Neumann: one constant per connected component, left out
    SolverStats stats;
};

/// The lowest `request.count` eigenpairs of K x = λ M x (M diagonal, positive): a dense solve
/// below 1200 unknowns (exact for any count), above it shift-invert Lanczos (Spectra), block
/// Lanczos or spectrum slicing (SLEPc), as chooseEigenMethod (EigenMethod.h) picks from `choice`
/// and the precompute's MPI ranks. Slicing needs `request.estimate`.
EigenPairs lowestEigenpairs(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                            const EigenRequest& request, EigensolverChoice choice);

/// |Ω| as the DOF cells measure it (Σ 1/⋆n).
double domainMeasure(const Eigen::VectorXd& cellStar);

/// Number of connected components of the DOF cells, linked through DOF faces, that touch no
/// open side: the constants in the Neumann Laplacian's kernel (an open side holds the pressure
/// at 0, so a component that reaches one has no constant mode).
int closedComponents(const CutCellDec& dec);

/// Dimension of the divergence-free space: faces − cells + closed components (rank of d is
/// cells − closed components because walls carry no flux).
std::int64_t divergenceFreeDimension(const CutCellDec& dec);

/// The first `count` non-constant Neumann scalar modes. `checkpoints`: where sliced solves keep
/// their finished intervals (SliceCheckpoint.h; empty: nowhere).
ScalarBasisResult solveNeumannScalarBasis(const CutCellDec& dec, int count,
                                          const SolveProgress& progress, EigensolverChoice choice,
                                          const IntervalCheckpoints& checkpoints);
ScalarBasisResult solveDirichletScalarBasis(const DirichletScalarDec& dec, int count,
                                            const SolveProgress& progress, EigensolverChoice choice,
                                            const IntervalCheckpoints& checkpoints);

/// The div-free modes in `ranges` (1-based, of the div-free spectrum, harmonic ones first).
/// Gradient eigenfields are pushed above the wanted range with a grad-div penalty chosen from
/// `firstNeumannEigenvalue` (μ₁²) and checked afterwards: if the top computed eigenvalue reaches
/// (1+s)μ₁² the solve is repeated with a larger s.
/// @throw Error when the ranges ask for more modes than the div-free space holds.
VelocityBasisResult solveVelocityBasis(const CutCellDec& dec, const std::vector<ModeRange>& ranges,
                                       double firstNeumannEigenvalue, double domainMeasure,
                                       const SolveProgress& progress, EigensolverChoice choice,
                                       const IntervalCheckpoints& checkpoints);

/// Reference eigenvalue scale (π/L)², L the largest extent of the grid box: shifts are relative to
/// it, and it anchors the search for the first non-zero κ² that decides which modes are harmonic.
double referenceEigenvalue(const GridSpec& grid);

}  // namespace modeflow
