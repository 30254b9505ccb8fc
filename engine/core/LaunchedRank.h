#pragma once
/// @file LaunchedRank.h
/// Where an MPI launcher put this process, read from the environment it gives its processes
/// (Open MPI's mpirun, MPICH's hydra, PMIx and Slurm's srun), without initializing MPI: every
/// command needs it to know whether it runs once or several times, and only `precompute` may
/// initialize MPI.

namespace modeflow {

struct LaunchedRank {
    bool launched = false;  ///< an MPI launcher started this process (`mpirun -n 1` too)
    int rank = 0;
    int size = 1;  ///< the ranks it started; 1 when unknown or not launched
    bool primary() const { return rank == 0; }
};

/// This process's place, or {false, 0, 1} when no launcher started it.
LaunchedRank launchedRank();

}  // namespace modeflow
