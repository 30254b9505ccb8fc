#include "precompute/solve/ShiftInvertEigensolver.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <new>

#include <Eigen/CholmodSupport>
#include <Spectra/SymEigsShiftSolver.h>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CHOLMOD's status after a call, as our error naming the stage; nothing on success.
void requireCholmodSuccess(const cholmod_common& common, const std::string& what,
                           Eigen::Index unknowns) {
    const std::string factor =
        "the sparse Cholesky factorization of " + std::to_string(unknowns) + " unknowns";
    switch (common.status) {
        case CHOLMOD_OK:
            return;
        case CHOLMOD_NOT_POSDEF:
            throw Error(what +
                        ": the sparse Cholesky factorization failed (the operator is not positive "
                        "definite after the shift)");
        case CHOLMOD_DSMALL:
            throw Error(what +
                        ": the sparse Cholesky factorization failed (the operator is too "
                        "ill-conditioned: a pivot is nearly zero)");
        case CHOLMOD_OUT_OF_MEMORY:
            throw Error("out of memory in " + what + " (" + factor + "); lower [grid].resolution");
        case CHOLMOD_TOO_LARGE:
            throw Error(what + ": " + factor +
                        " is too large for CHOLMOD's integers; lower [grid].resolution");
        default:
            throw Error(what + ": " + factor + " failed (CHOLMOD status " +
                        std::to_string(common.status) + ")");
    }
}

/// (A − σI)⁻¹ for the symmetrically scaled A = M^{-1/2} K M^{-1/2}: a diagonal M turns the
/// generalized problem into a standard one, so Lanczos needs no M-inner products.
class ScaledShiftInvert {
public:
    using Scalar = double;

    ScaledShiftInvert(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                      const EigenRequest& request)
        : mK(k), mM(m), mRequest(request) {
        // CHOLMOD prints its warnings on stdout; its status becomes our message instead.
        mSolver.cholmod().print = 0;
    }

    Eigen::Index rows() const { return mK.rows(); }
    Eigen::Index cols() const { return mK.cols(); }

    void set_shift(const Scalar& sigma) {
        Eigen::SparseMatrix<double> shifted = mK;
        for (Eigen::Index i = 0; i < mM.size(); ++i) shifted.coeffRef(i, i) -= sigma * mM[i];
        const auto start = std::chrono::steady_clock::now();
        mSolver.analyzePattern(shifted);
        // A failed analysis leaves no factor, which Eigen's factorize() would dereference.
        requireCholmodSuccess(mSolver.cholmod(), mRequest.what, rows());
        mSolver.factorize(shifted);
        mStats.factorSeconds += secondsSince(start);
        requireCholmodSuccess(mSolver.cholmod(), mRequest.what, rows());
        mScale = mM.cwiseSqrt();
    }

    // y = M^{1/2} (K − σM)⁻¹ M^{1/2} x
    void perform_op(const Scalar* xIn, Scalar* yOut) const {
        Eigen::Map<const Eigen::VectorXd> x(xIn, rows());
        Eigen::Map<Eigen::VectorXd> y(yOut, rows());
        const auto start = std::chrono::steady_clock::now();
        y = mScale.cwiseProduct(mSolver.solve(mScale.cwiseProduct(x)));
        mStats.solveSeconds += secondsSince(start);
        ++mStats.operations;
        if (mRequest.progress && mStats.operations % 16 == 0) mRequest.progress(mStats.operations);
    }

    const SolverStats& stats() const { return mStats; }

private:
    const Eigen::SparseMatrix<double>& mK;
    const Eigen::VectorXd& mM;
    const EigenRequest& mRequest;
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> mSolver;
    Eigen::VectorXd mScale;
    mutable SolverStats mStats;
};

}  // namespace

EigenPairs smallestEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                              const Eigen::VectorXd& massDiagonal, const EigenRequest& request) {
    const Eigen::Index n = stiffness.rows();
    if (request.count < 1 || request.count >= n)
        throw Error(request.what + ": asked for " + std::to_string(request.count) +
                    " eigenpairs of a " + std::to_string(n) + "-dimensional space");
    ScaledShiftInvert op(stiffness, massDiagonal, request);
    const Eigen::Index nev = request.count;
    // ncv = 1.5 nev needed fewer solves and less time than the textbook 2 nev (48³ ball, 100 modes:
    // 334 against 406 solves, 47 s against 58 s): the Krylov basis is re-orthogonalized at every
    // step, and its bandwidth grows with ncv.
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(3 * nev / 2 + 1, nev + 30));
    Spectra::SymEigsShiftSolver<ScaledShiftInvert> solver(op, nev, ncv, request.shift);
    try {
        solver.init();
        solver.compute(Spectra::SortRule::LargestMagn, 1000, request.tolerance,
                       Spectra::SortRule::SmallestAlge);
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        // Spectra's own failures (a NaN in the Krylov basis: the operator overflowed).
        throw Error(request.what + ": Lanczos failed (" + e.what() + ")");
    }
    if (solver.info() != Spectra::CompInfo::Successful)
        throw Error(request.what + ": Lanczos did not converge for " + std::to_string(nev) +
                    " eigenpairs (" + std::to_string(solver.num_iterations()) + " restarts)");
    EigenPairs out;
    out.values = solver.eigenvalues();
    out.vectors = solver.eigenvectors();
    const Eigen::VectorXd invScale = massDiagonal.cwiseSqrt().cwiseInverse();
    out.vectors = invScale.asDiagonal() * out.vectors;
    out.stats = op.stats();
    out.stats.restarts = solver.num_iterations();
    return out;
}

}  // namespace modeflow
