#pragma once
/// @file ProcessGroup.h
/// The processes one precompute runs on: this one alone, or the K ranks `mpirun -n K` started.
/// MPI and PETSc are loaded and initialized only when needed (SlicedEigensolver.h, or
/// joinProcessGroup() under an MPI launcher: PetscRuntime.h) and finalized at exit; nothing else
/// in the project sees them.

#include <string>

namespace modeflow {

struct ProcessGroup {
    int rank = 0;
    int size = 1;
    /// Groups of ranks that solve spectrum subintervals side by side (SlicedEigensolver.h), each
    /// factorizing with MUMPS on its size / partitions ranks: PETSc's option
    /// -eps_krylovschur_partitions (PETSC_OPTIONS) where a user set it, else one per rank.
    int partitions = 1;
    bool primary() const { return rank == 0; }
};

/// Called once at the start of `modeflow precompute`: under an MPI launcher (mpirun, srun:
/// recognized by the environment it gives its processes) initializes MPI and PETSc so that every
/// rank knows its place before any work; alone, initializes nothing and returns {0, 1, 1}.
/// @throw Error when MPI or PETSc cannot be initialized, or -eps_krylovschur_partitions is not
///        between 1 and the number of ranks.
ProcessGroup joinProcessGroup();

/// The group as it stands: {0, 1, 1} while MPI was never initialized.
/// @throw Error as joinProcessGroup() for the partitions.
ProcessGroup currentProcessGroup();

/// Initializes MPI (a singleton group when no launcher started this process) and PETSc with
/// SLEPc, once per process; finalized at exit.
/// @throw Error when they cannot be initialized.
void ensurePetsc();

/// What PETSc said where its last error was raised ("-mat_mumps_icntl_24 must be set …"), for
/// error messages; PETSc itself prints nothing.
std::string lastPetscErrorMessage();

}  // namespace modeflow
