#include "precompute/solve/BlockLanczos.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <cblas.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "engine/core/Error.h"
#include "precompute/solve/HugePages.h"

namespace modeflow {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

/// A new direction whose part outside the search space is below this fraction of its length is
/// round-off: the space already holds it (an invariant subspace reached, or every copy of an
/// eigenvalue found), and a random direction takes its place.
constexpr double kLostFraction = 1e-10;

/// Rows per pass when the space is rotated onto its Ritz vectors in place.
constexpr Index kRotationRows = 4096;

/// Uniform entries from a fixed seed: runs repeat to the bit.
class RandomColumns {
public:
    void fill(Eigen::Ref<MatrixXd> m) {
        for (Index c = 0; c < m.cols(); ++c)
            for (Index r = 0; r < m.rows(); ++r) m(r, c) = mUniform(mRandom);
    }

private:
    std::mt19937_64 mRandom{0x5eed};
    std::uniform_real_distribution<double> mUniform{-0.5, 0.5};
};

/// c = α op(a) b + β c through BLAS (OpenBLAS), op(a) = aᵀ where `transposed`. Not Eigen's
/// product: it packs a product's whole left side into a fresh buffer on every call, and for the
/// search space's tall products that buffer is as large as the space: on the seed's sphere scene
/// 99% of the eigensolve's page faults, and half its time. BLAS keeps its buffers.
void gemm(bool transposed, double alpha, const Eigen::Ref<const MatrixXd>& a,
          const Eigen::Ref<const MatrixXd>& b, double beta, Eigen::Ref<MatrixXd> c) {
    const auto k = int(transposed ? a.rows() : a.cols());
    cblas_dgemm(CblasColMajor, transposed ? CblasTrans : CblasNoTrans, CblasNoTrans, int(c.rows()),
                int(c.cols()), k, alpha, a.data(), int(a.outerStride()), b.data(),
                int(b.outerStride()), beta, c.data(), int(c.outerStride()));
}

/// aᵀ b.
MatrixXd innerProducts(const Eigen::Ref<const MatrixXd>& a, const Eigen::Ref<const MatrixXd>& b) {
    MatrixXd c(a.cols(), b.cols());
    if (a.rows() > 0)
        gemm(true, 1.0, a, b, 0.0, c);
    else
        c.setZero();
    return c;
}

/// Removes from `block` its parts along the orthonormal columns of `basis`.
void project(const Eigen::Ref<const MatrixXd>& basis, Eigen::Ref<MatrixXd> block) {
    if (basis.cols() > 0) gemm(false, -1.0, basis, innerProducts(basis, block), 1.0, block);
}

/// Cholesky QR trusts a column whose part outside the columns before it is at least this fraction
/// of its length: its loss of orthogonality, about ε·cond², is then removed by a second pass.
constexpr double kCholeskyTrust = 1e-5;

/// x ← x R⁻¹ with RᵀR = xᵀx (Cholesky QR: a Gram matrix and a triangular solve, BLAS-3 on every
/// core, where Householder QR works a column at a time on one core); returns R's diagonal, or an
/// empty vector (x unchanged) when the Gram matrix is too ill-conditioned to trust
/// (kCholeskyTrust).
VectorXd choleskyQr(Eigen::Ref<MatrixXd> x) {
    const MatrixXd gram = innerProducts(x, x);
    const Eigen::LLT<MatrixXd> llt(gram);
    if (llt.info() != Eigen::Success) return {};
    const MatrixXd r = llt.matrixU();
    for (Index c = 0; c < x.cols(); ++c)
        if (!(r(c, c) >= kCholeskyTrust * std::sqrt(gram(c, c)))) return {};
    cblas_dtrsm(CblasColMajor, CblasRight, CblasUpper, CblasNoTrans, CblasNonUnit, int(x.rows()),
                int(x.cols()), 1.0, r.data(), int(r.outerStride()), x.data(), int(x.outerStride()));
    return r.diagonal();
}

/// The search space of one run: orthonormal columns Q (orthogonal to the deflated ones) and the
/// Rayleigh quotient H = Qᵀ A Q, filled a block at a time, with the next block N and R such that
/// A Q = Q H + N R E_lastᵀ (block Lanczos's relation: only the last block's image reaches outside
/// the space). Every large array is allocated once, in huge pages (HugePages.h).
class SearchSpace {
public:
    SearchSpace(const BlockApply& apply, Index size, Index capacity, Index blockSize,
                const MatrixXd& deflated, const std::string& what)
        : mApply(apply),
          mDeflated(deflated),
          mWhat(what),
          mQPages(size, capacity),
          mImagePages(size, blockSize),
          mScratchPages(size, blockSize),
          mNextPages(size, blockSize),
          mQ(mQPages.map()),
          mImage(mImagePages.map()),
          mScratch(mScratchPages.map()),
          mNext(mNextPages.map()),
          mH(MatrixXd::Zero(capacity, capacity)) {
        mRandom.fill(mImage);
        project(mDeflated, mImage);
        findNext(mImage.colwise().norm().transpose());
    }

    Index filled() const { return mFilled; }
    Index capacity() const { return mQ.cols(); }
    Index blockSize() const { return mNext.cols(); }
    long applied() const { return mApplied; }

    /// Adds the next block with the Rayleigh quotient's new columns, which the first pass of
    /// block Gram–Schmidt against the space gives, and finds the block after it.
    void grow() {
        const Index b = blockSize(), j = mFilled;
        mQ.middleCols(j, b) = mNext;
        mApply(mNext, mImage);
        mApplied += b;
        project(mDeflated, mImage);
        mFilled = j + b;
        const MatrixXd c = innerProducts(mQ.leftCols(mFilled), mImage);
        mH.block(0, j, mFilled, b) = c;
        mH.block(j, 0, b, mFilled) = c.transpose();
        mH.block(j, j, b, b) = 0.5 * (c.bottomRows(b) + c.bottomRows(b).transpose());
        const VectorXd lengths = mImage.colwise().norm().transpose();
        gemm(false, -1.0, mQ.leftCols(mFilled), c, 1.0, mImage);
        findNext(lengths);
    }

    /// Rayleigh–Ritz: the largest `keep` Ritz pairs of the space, which then becomes their span
    /// (a thick restart: the next block stays orthogonal to it, so the Krylov sequence goes on).
    /// Returns the values, descending; `converged` counts the leading pairs within `tolerance`.
    VectorXd restart(Index keep, Index wanted, double tolerance, Index& converged) {
        Eigen::SelfAdjointEigenSolver<MatrixXd> eig(mH.topLeftCorner(mFilled, mFilled));
        if (eig.info() != Eigen::Success)
            throw Error(mWhat + ": the block Lanczos Rayleigh quotient has no eigenbasis");
        const VectorXd values = eig.eigenvalues().reverse().head(keep);
        const MatrixXd s = eig.eigenvectors().rowwise().reverse().leftCols(keep);
        // For y = Q s with H s = θ s, A y − θ y = N R s_last: its length costs no product with Q.
        const MatrixXd residuals = mR * s.bottomRows(blockSize());
        converged = 0;
        while (converged < wanted &&
               residuals.col(converged).norm() <= tolerance * std::abs(values[converged]))
            ++converged;
        // Q ← Q s row by row: each row of the product needs only the same row of Q.
        MatrixXd rows(std::min(kRotationRows, mQ.rows()), keep);
        for (Index r = 0; r < mQ.rows(); r += rows.rows()) {
            const Index count = std::min(rows.rows(), mQ.rows() - r);
            gemm(false, 1.0, mQ.block(r, 0, count, mFilled), s, 0.0, rows.topRows(count));
            mQ.block(r, 0, count, keep) = rows.topRows(count);
        }
        // The relation holds on with the new columns: H = diag(θ), the next block unchanged.
        mH.setZero();
        mH.topLeftCorner(keep, keep).diagonal() = values;
        mFilled = keep;
        return values;
    }

    MatrixXd vectors(Index count) const { return mQ.leftCols(count); }

private:
    /// The next block: an orthonormal basis of mImage (whose parts along the deflated columns
    /// and the space were removed once; `lengths` its columns' lengths before) orthogonal to
    /// both, and R = Nᵀ mImage. Columns with nothing left become random ones.
    void findNext(const VectorXd& lengths) {
        mScratch = mImage;
        if (!nextByCholesky(lengths)) nextByHouseholder(lengths);
    }

    /// findNext by Cholesky QR (block Gram–Schmidt with it, BCGS2): normalize, project once more,
    /// normalize twice. False, with only mScratch changed, where a column has too little left to
    /// trust it (lost, or nearly in the span of the others: Householder QR decides then).
    bool nextByCholesky(const VectorXd& lengths) {
        const VectorXd diagonal = choleskyQr(mScratch);
        if (diagonal.size() == 0) return false;
        for (Index c = 0; c < diagonal.size(); ++c)
            if (!(diagonal[c] > kLostFraction * lengths[c])) return false;
        project(mDeflated, mScratch);
        project(mQ.leftCols(mFilled), mScratch);
        for (int pass = 0; pass < 2; ++pass)
            if (choleskyQr(mScratch).size() == 0) return false;
        mNext = mScratch;
        mR = innerProducts(mNext, mImage);
        return true;
    }

    /// findNext by Householder QR, which also replaces columns with nothing left by random ones.
    void nextByHouseholder(VectorXd lengths) {
        const Index b = blockSize();
        mScratch = mImage;
        for (int attempt = 0; attempt < 8; ++attempt) {
            mNext = mScratch;
            const Eigen::HouseholderQR<Eigen::Ref<MatrixXd>> qr(mNext);
            bool lost = false;
            for (Index c = 0; c < b; ++c) {
                if (std::abs(qr.matrixQR()(c, c)) > kLostFraction * lengths[c]) continue;
                mRandom.fill(mScratch.col(c));
                lengths[c] = mScratch.col(c).norm();
                lost = true;
            }
            if (lost) {
                project(mDeflated, mScratch);
                project(mQ.leftCols(mFilled), mScratch);
                continue;
            }
            mScratch.setIdentity();
            mScratch.applyOnTheLeft(qr.householderQ());
            // Twice is enough: what was left of a column can be small against its length, so
            // its first orthonormal form is orthogonal to the space only to round-off over that.
            project(mDeflated, mScratch);
            project(mQ.leftCols(mFilled), mScratch);
            const Eigen::HouseholderQR<Eigen::Ref<MatrixXd>> again(mScratch);
            mNext.setIdentity();
            mNext.applyOnTheLeft(again.householderQ());
            mR = innerProducts(mNext, mImage);
            return;
        }
        throw Error(mWhat + ": block Lanczos found no new directions (the space has only " +
                    std::to_string(mFilled + mDeflated.cols()) + " dimensions)");
    }

    const BlockApply& mApply;
    const MatrixXd& mDeflated;
    const std::string& mWhat;
    RandomColumns mRandom;
    HugePageMatrix mQPages, mImagePages, mScratchPages, mNextPages;
    Eigen::Map<MatrixXd>& mQ;
    Eigen::Map<MatrixXd>& mImage;    ///< A times the newest block, then its part outside the space
    Eigen::Map<MatrixXd>& mScratch;  ///< the next block's workspace
    Eigen::Map<MatrixXd>& mNext;
    MatrixXd mH, mR;
    Index mFilled = 0;
    long mApplied = 0;
};

}  // namespace

BlockLanczosResult largestEigenpairs(const BlockApply& apply, Eigen::Index size,
                                     const Eigen::MatrixXd& deflated,
                                     const BlockLanczosRequest& request) {
    const Index b = request.blockSize, nev = request.count;
    // The space holds the wanted pairs and as many more vectors again (at least four blocks);
    // a restart keeps a quarter of the extra ones, which speeds the wanted pairs' convergence.
    const Index room = size - deflated.cols() - b;
    const Index capacity = std::min(room, nev + std::max(nev, 4 * b));
    if (nev < 1 || b < 1 || capacity < nev + b)
        throw Error(request.what + ": " + std::to_string(nev) + " eigenpairs in blocks of " +
                    std::to_string(b) + " need more than the " + std::to_string(size) +
                    " dimensions of the space");
    const Index keep = std::min(nev + (capacity - nev) / 4, capacity - b);
    SearchSpace space(apply, size, capacity, b, deflated, request.what);
    BlockLanczosResult out;
    for (int restart = 0;; ++restart) {
        while (space.filled() + b <= space.capacity()) space.grow();
        Index converged = 0;
        const VectorXd values = space.restart(keep, nev, request.tolerance, converged);
        if (converged == nev) {
            out.values = values.head(nev);
            out.vectors = space.vectors(nev);
            out.applied = space.applied();
            out.restarts = restart;
            return out;
        }
        if (restart == request.maxRestarts)
            throw Error(request.what + ": block Lanczos did not converge for " +
                        std::to_string(nev) + " eigenpairs (" + std::to_string(converged) +
                        " converged after " + std::to_string(restart) + " restarts)");
    }
}

}  // namespace modeflow
