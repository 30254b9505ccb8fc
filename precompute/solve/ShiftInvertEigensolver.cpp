#include "precompute/solve/ShiftInvertEigensolver.h"

#include <algorithm>
#include <chrono>

#include <Eigen/CholmodSupport>
#include <Spectra/SymEigsShiftSolver.h>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// (A − σI)⁻¹ for the symmetrically scaled A = M^{-1/2} K M^{-1/2}: a diagonal M turns the
/// generalized problem into a standard one, so Lanczos needs no M-inner products.
class ScaledShiftInvert {
public:
    using Scalar = double;

    ScaledShiftInvert(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                      const EigenRequest& request)
        : mK(k), mM(m), mRequest(request) {}

    Eigen::Index rows() const { return mK.rows(); }
    Eigen::Index cols() const { return mK.cols(); }

    void set_shift(const Scalar& sigma) {
        Eigen::SparseMatrix<double> shifted = mK;
        for (Eigen::Index i = 0; i < mM.size(); ++i) shifted.coeffRef(i, i) -= sigma * mM[i];
        const auto start = std::chrono::steady_clock::now();
        mSolver.analyzePattern(shifted);
        mSolver.factorize(shifted);
        mStats.factorSeconds += secondsSince(start);
        if (mSolver.info() != Eigen::Success)
            throw Error(mRequest.what + ": the sparse Cholesky factorization failed (the operator "
                                        "is not positive definite after the shift)");
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
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, request.tolerance,
                   Spectra::SortRule::SmallestAlge);
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
