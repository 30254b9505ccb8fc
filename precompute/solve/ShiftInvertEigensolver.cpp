#include "precompute/solve/ShiftInvertEigensolver.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <Eigen/CholmodSupport>
#include <Spectra/SymEigsShiftSolver.h>

#include "engine/format/Error.h"

namespace modeflow {
namespace {

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
        auto t0 = std::chrono::steady_clock::now();
        mSolver.analyzePattern(shifted);
        mSolver.factorize(shifted);
        mFactorSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (mSolver.info() != Eigen::Success)
            throw Error(mRequest.what + ": the sparse Cholesky factorization failed (the operator "
                                        "is not positive definite after the shift)");
        mScale = mM.cwiseSqrt();
    }

    // y = M^{1/2} (K − σM)⁻¹ M^{1/2} x
    void perform_op(const Scalar* xIn, Scalar* yOut) const {
        Eigen::Map<const Eigen::VectorXd> x(xIn, rows());
        Eigen::Map<Eigen::VectorXd> y(yOut, rows());
        auto t0 = std::chrono::steady_clock::now();
        y = mScale.cwiseProduct(mSolver.solve(mScale.cwiseProduct(x)));
        mSolveSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ++mOperations;
        if (mRequest.progress && mOperations % 16 == 0) mRequest.progress(mOperations);
    }

    long operations() const { return mOperations; }

private:
    const Eigen::SparseMatrix<double>& mK;
    const Eigen::VectorXd& mM;
    const EigenRequest& mRequest;
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> mSolver;
    Eigen::VectorXd mScale;
    mutable long mOperations = 0;
public:
    mutable double mSolveSeconds = 0, mFactorSeconds = 0;
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
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * nev + 1, nev + 30));
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
    out.operations = op.operations();
    out.restarts = solver.num_iterations();
    if (std::getenv("MODEFLOW_DEBUG_SOLVER")) std::fprintf(stderr, "[%s] n=%ld nev=%ld ncv=%ld ops=%ld restarts=%ld factor=%.2fs solves=%.2fs\n", request.what.c_str(), long(n), long(nev), long(ncv), out.operations, out.restarts, op.mFactorSeconds, op.mSolveSeconds);
    return out;
}

}  // namespace modeflow
