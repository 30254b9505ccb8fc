#pragma once
/// @file SliceCheckpoint.h
/// The finished intervals of a sliced eigensolve (SlicedEigensolver.h) as files beside the cache
/// they are for, so that a precompute killed after some intervals (Ctrl-C, out of memory, a lost
/// rank) resumes from them: `<cache stem>.<problem>.<interval>.mfslice`. Each holds the
/// interval's eigenpairs and what identifies them: a hash of the operator and the request, the
/// interval's place in the sequence and its ends. The sequence is deterministic for the same
/// inputs (the first end comes from the request's estimate, every later one from the exact
/// inertia counts so far), so an interval of a rerun is the stored one when these agree.

#include <cstdint>
#include <filesystem>

#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {

struct SliceCheckpoint {
    std::uint64_t problem = 0;  ///< sliceProblemHash() of the solve it belongs to
    int interval = 0;           ///< its place in the solve's sequence of intervals, from 0
    double lo = 0.0, hi = 0.0;  ///< the ends of the interval [lo, hi) of the spectrum
    Eigen::VectorXd values;     ///< every eigenvalue in it, ascending
    Eigen::MatrixXd vectors;    ///< their M-orthonormal vectors, as columns
};

/// Hash of K, diag(M) and what the request asks (count, shift, estimate, tolerance, dimension):
/// equal for the same eigenproblem, whatever the process count.
std::uint64_t sliceProblemHash(const Eigen::SparseMatrix<double>& stiffness,
                               const Eigen::VectorXd& massDiagonal, const EigenRequest& request);

/// `<cachePath without .mfbasis>.<problem in hex>.<interval>.mfslice`.
std::filesystem::path sliceCheckpointPath(const std::filesystem::path& cachePath,
                                          std::uint64_t problem, int interval);

/// Written atomically (engine/core/AtomicFile.h), with a magic, a version and a checksum.
/// @throw Error naming the file when it cannot be written.
void writeSliceCheckpoint(const std::filesystem::path& path, const SliceCheckpoint& checkpoint);

/// The checkpoint at `path` when it is whole and holds interval `interval` of `problem`, starting
/// at `lo`, with vectors of `rows` entries.
/// @throw Error naming the file and what is wrong with it (damaged, of another version, of
///        another eigenproblem or interval).
SliceCheckpoint readSliceCheckpoint(const std::filesystem::path& path, std::uint64_t problem,
                                    int interval, double lo, Eigen::Index rows);

/// Removes every checkpoint of the cache at `cachePath` (once the cache is written); returns how
/// many. Files that cannot be removed are left.
int removeSliceCheckpoints(const std::filesystem::path& cachePath);

}  // namespace modeflow
