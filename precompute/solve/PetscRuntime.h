#pragma once
/// @file PetscRuntime.h
/// What the sliced eigensolver (SlicedEigensolver.h) and the process group (ProcessGroup.h) ask
/// of PETSc, SLEPc and MPI. Those libraries live in a module of their own
/// (precompute/solve/petsc, libmodeflow_petsc.so), loaded by the first call that needs them: a
/// command that slices nothing and runs outside `mpirun` never loads them, and starts without
/// the hundred libraries they bring (tools/README.md, "Start-up").

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "precompute/solve/ProcessGroup.h"
#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {

/// K x = λ M x with K and diag(M) distributed by rows over every rank.
class DistributedEigenproblem {
public:
    virtual ~DistributedEigenproblem() = default;
    /// Every eigenpair in [lo, hi), vectors M-orthonormal, on every rank, the partitions solving
    /// the subintervals between `ends` (lo, …, hi; empty with one partition); nothing when a
    /// shift lies on an eigenvalue (the caller moves the end). Adds its counts to `stats`.
    /// @throw Error naming the request's solve when PETSc, SLEPc or MUMPS fail.
    virtual std::optional<EigenPairs> solveInterval(double lo, double hi,
                                                    const std::vector<double>& ends,
                                                    SolverStats& stats) = 0;
};

class PetscRuntime {
public:
    virtual ~PetscRuntime() = default;
    /// Initializes MPI (a singleton group without a launcher) and PETSc with SLEPc, once per
    /// process; they are finalized at exit. @throw Error when they cannot be initialized.
    virtual void start() = 0;
    virtual bool started() const = 0;
    /// The ranks, this rank and the partitions (ProcessGroup.h); after start().
    /// @throw Error for -eps_krylovschur_partitions outside 1 … ranks.
    virtual ProcessGroup group() const = 0;
    /// What PETSc said where its last error was raised.
    virtual std::string lastError() const = 0;
    /// The problem distributed over the ranks, for `request` (its tolerance, progress and name);
    /// starts the runtime first. @throw Error as solveInterval.
    virtual std::unique_ptr<DistributedEigenproblem> distribute(
        const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& massDiagonal,
        const EigenRequest& request) = 0;
    /// Rank 0's values to every rank (collective).
    virtual void broadcast(long& value) = 0;
    virtual void broadcast(double* values, Eigen::Index count) = 0;
};

/// The runtime, its module loaded by the first call.
/// @throw Error naming the module's file when it cannot be loaded.
PetscRuntime& petscRuntime();

/// Whether the module was loaded (MPI and PETSc cannot have started otherwise).
bool petscRuntimeLoaded();

}  // namespace modeflow

/// The module's one entry point (dlsym), a runtime that lives as long as the process.
extern "C" modeflow::PetscRuntime* modeflow_petsc_runtime();
