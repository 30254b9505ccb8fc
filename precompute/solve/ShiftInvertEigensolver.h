#pragma once
/// @file ShiftInvertEigensolver.h
/// Lowest eigenpairs of K x = λ M x (K sparse symmetric positive semi-definite, M diagonal
/// positive) by shift-invert Lanczos (Spectra, or block Lanczos) around a sparse Cholesky
/// factorization (CHOLMOD).
/// Spectra and CHOLMOD headers stay inside the .cpp.

#include <filesystem>
#include <functional>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace modeflow {

/// What a solve cost, for progress lines and `inspect` timings.
struct SolverStats {
    long operations = 0;  ///< shift-invert solves performed
    long restarts = 0;    ///< Lanczos restarts
    long factorizations = 0;
    double factorSeconds = 0.0;
    double solveSeconds = 0.0;

    SolverStats& operator+=(const SolverStats& o) {
        operations += o.operations;
        restarts += o.restarts;
        factorizations += o.factorizations;
        factorSeconds += o.factorSeconds;
        solveSeconds += o.solveSeconds;
        return *this;
    }
};

struct EigenPairs {
    Eigen::VectorXd values;   ///< ascending
    Eigen::MatrixXd vectors;  ///< columns, M-orthonormal
    SolverStats stats;
};

/// Called with the number of solves done so far (for progress on a terminal).
using SolveProgress = std::function<void(long operations)>;

/// Where the sliced solver keeps its finished intervals, so that an interrupted precompute
/// resumes from them (SliceCheckpoint.h), and how it says what it reused or refused.
struct IntervalCheckpoints {
    std::filesystem::path cachePath;  ///< the cache they are for; empty: none are kept
    std::function<void(const std::string& message)> note;
};

struct EigenRequest {
    int count = 0;
    /// Shift σ < 0 below the spectrum: K − σM stays positive definite even when K has a
    /// null space (harmonic fields, constants), which σ = 0 would make singular.
    double shift = -1.0;
    double tolerance = 1e-12;
    std::string what;  ///< named in error messages ("velocity eigensolve")
    SolveProgress progress;
    /// The operator has eigenvalues of high multiplicity (the translations and reflections of
    /// periodic axes: up to 16 equal κ² on a 3D torus). Lanczos from one start vector finds one
    /// vector per eigenspace in exact arithmetic and the other copies only through round-off,
    /// so it can miss some (3D torus 10×8×12, 70 modes: 8 of the 16 copies of one κ²). With this
    /// set, further Lanczos runs on the operator deflated by the pairs found so far look for
    /// eigenvalues below the highest one kept, until a run finds none. They also run whenever
    /// the first run finds two eigenvalues equal to round-off: a domain with symmetries (a ball
    /// centred in the grid: 16³, 20 scalar modes missed one of two copies of a κ²).
    bool findMissedCopies = false;
    /// Where the `count`-th eigenvalue is expected (Weyl's law) and the d of N(λ) ∝ λ^{d/2}: the
    /// sliced solver's first interval ends there, and intervals grow by that law
    /// (SlicedEigensolver.h).
    double estimate = 0.0;
    int spectralDimension = 3;
    IntervalCheckpoints checkpoints{};  ///< used by the sliced solver only
};

/// How the shift-invert operator is searched: a vector at a time (Spectra's Lanczos) or a block
/// at a time (BlockLanczos.h: several right-hand sides per solve, dense products on every core).
enum class KrylovMethod { Lanczos, BlockLanczos };

/// @throw Error naming `what` when the factorization fails or the search does not converge.
EigenPairs smallestEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                              const Eigen::VectorXd& massDiagonal, const EigenRequest& request,
                              KrylovMethod method = KrylovMethod::Lanczos);

}  // namespace modeflow
