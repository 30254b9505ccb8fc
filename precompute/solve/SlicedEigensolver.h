#pragma once
/// @file SlicedEigensolver.h
/// Lowest eigenpairs of K x = λ M x (K sparse symmetric positive semi-definite, M diagonal
/// positive) by spectrum slicing: SLEPc's Krylov–Schur on intervals [a, b] of the spectrum, each
/// cut into subintervals solved independently around MUMPS LDLᵀ factorizations whose inertia
/// counts the eigenvalues below every shift, so none is lost or found twice. Per mode the cost
/// stays about flat as the count grows, where one shift-invert Lanczos run around one shift
/// (ShiftInvertEigensolver.h) slows down. Under `mpirun -n K` the subintervals run on the K ranks
/// (SLEPc's partitions: one per rank, or as many as PETSc's option -eps_krylovschur_partitions
/// says, each factorizing with MUMPS on its K / partitions ranks) and every rank receives every
/// pair. PETSc, SLEPc and MPI stay in their module (PetscRuntime.h).
///
/// The intervals: the first runs from `request.shift` to a little above `request.estimate`;
/// while fewer than `count` eigenvalues are found, the next one starts where the last ended and
/// reaches where N(λ) ∝ λ^{d/2} (Weyl), fitted to the count so far, puts the rest. With
/// `request.checkpoints` set, every finished interval is kept beside the cache (SliceCheckpoint.h)
/// and the intervals an interrupted run kept are read instead of solved.

#include <vector>

#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {

/// @throw Error naming `request.what` when PETSc, SLEPc or MUMPS fail, or when the intervals
/// stop finding eigenvalues before `count`.
EigenPairs slicedEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                            const Eigen::VectorXd& massDiagonal, const EigenRequest& request);

/// The `parts` + 1 ends of subintervals of [lo, hi] holding about equally many eigenvalues when
/// N(λ) ∝ λ^{d/2} (a negative lo counts as 0 for the law): lo and hi included, ascending.
std::vector<double> weylSubintervals(double lo, double hi, int parts, int dimension);

}  // namespace modeflow
