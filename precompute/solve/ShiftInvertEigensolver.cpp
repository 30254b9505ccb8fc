#include "precompute/solve/ShiftInvertEigensolver.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <new>
#include <numeric>
#include <random>
#include <vector>

#include <Spectra/SymEigsShiftSolver.h>
#include <Eigen/CholmodSupport>

#include "engine/core/Error.h"
#include "precompute/solve/BlockLanczos.h"
#include "precompute/solve/HugePages.h"

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

/// Eigen's supernodal Cholesky with its factor at hand, for CHOLMOD's solve into reused arrays.
class SupernodalCholesky
    : public Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
public:
    cholmod_factor* factor() const { return m_cholmodFactor; }
};

/// The factorization of K − σM, made once and shared by every Lanczos run of a solve.
class ShiftedFactor {
public:
    ShiftedFactor(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m, double sigma,
                  const EigenRequest& request, SolverStats& stats)
        : mScale(m.cwiseSqrt()), mRequest(request), mStats(stats) {
        useHugePagesForSuiteSparse();
        // CHOLMOD prints its warnings on stdout; its status becomes our message instead.
        mSolver.cholmod().print = 0;
        Eigen::SparseMatrix<double> shifted = k;
        for (Eigen::Index i = 0; i < m.size(); ++i) shifted.coeffRef(i, i) -= sigma * m[i];
        const auto start = std::chrono::steady_clock::now();
        ++mStats.factorizations;
        mSolver.analyzePattern(shifted);
        // A failed analysis leaves no factor, which Eigen's factorize() would dereference.
        requireCholmodSuccess(mSolver.cholmod(), request.what, k.rows());
        mSolver.factorize(shifted);
        mStats.factorSeconds += secondsSince(start);
        requireCholmodSuccess(mSolver.cholmod(), request.what, k.rows());
    }

    ShiftedFactor(const ShiftedFactor&) = delete;
    ShiftedFactor& operator=(const ShiftedFactor&) = delete;

    ~ShiftedFactor() {
        for (cholmod_dense** d : {&mSolution, &mWork, &mWorkE})
            cholmod_free_dense(d, &mSolver.cholmod());
    }

    Eigen::Index size() const { return mScale.size(); }
    /// M^{1/2} diagonal: scaled vectors are M^{1/2} x.
    const Eigen::VectorXd& scale() const { return mScale; }

    /// y = M^{1/2} (K − σM)⁻¹ M^{1/2} x, for one vector or a block of them (one CHOLMOD solve
    /// with several right-hand sides, into arrays kept from one call to the next: a fresh
    /// block-sized array costs its page faults every time).
    void apply(const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::Ref<Eigen::MatrixXd> y) const {
        const auto start = std::chrono::steady_clock::now();
        mRight.noalias() = mScale.asDiagonal() * x;
        cholmod_dense right = Eigen::viewAsCholmod(mRight);
        cholmod_solve2(CHOLMOD_A, mSolver.factor(), &right, nullptr, &mSolution, nullptr, &mWork,
                       &mWorkE, &mSolver.cholmod());
        requireCholmodSuccess(mSolver.cholmod(), mRequest.what, size());
        y.noalias() =
            mScale.asDiagonal() * Eigen::Map<const Eigen::MatrixXd>(
                                      static_cast<const double*>(mSolution->x), x.rows(), x.cols());
        mStats.solveSeconds += secondsSince(start);
        const long before = mStats.operations;
        mStats.operations += x.cols();
        if (mRequest.progress && mStats.operations / 16 != before / 16)
            mRequest.progress(mStats.operations);
    }

private:
    Eigen::VectorXd mScale;
    const EigenRequest& mRequest;
    SolverStats& mStats;
    mutable SupernodalCholesky mSolver;
    mutable Eigen::MatrixXd mRight;
    mutable cholmod_dense* mSolution = nullptr;
    mutable cholmod_dense* mWork = nullptr;
    mutable cholmod_dense* mWorkE = nullptr;
};

/// (A − σI)⁻¹ for the symmetrically scaled A = M^{-1/2} K M^{-1/2}: a diagonal M turns the
/// generalized problem into a standard one, so Lanczos needs no M-inner products. With
/// `deflated` (orthonormal columns), (I − QQᵀ)(A − σI)⁻¹(I − QQᵀ): the eigenpairs already found
/// move to 0, out of Lanczos's way.
class ScaledShiftInvert {
public:
    using Scalar = double;

    ScaledShiftInvert(const ShiftedFactor& factor, const Eigen::MatrixXd& deflated)
        : mFactor(factor), mDeflated(deflated) {}

    Eigen::Index rows() const { return mFactor.size(); }
    Eigen::Index cols() const { return mFactor.size(); }
    /// Spectra passes the shift it was made with, which the factor already holds.
    void set_shift(const Scalar&) {}

    void perform_op(const Scalar* xIn, Scalar* yOut) const {
        Eigen::Map<const Eigen::VectorXd> x(xIn, rows());
        Eigen::Map<Eigen::VectorXd> y(yOut, rows());
        Eigen::MatrixXd image(rows(), 1);
        mFactor.apply(project(x), image);
        y = project(image);
    }

    Eigen::VectorXd project(const Eigen::VectorXd& x) const {
        if (mDeflated.cols() == 0) return x;
        return x - mDeflated * (mDeflated.transpose() * x);
    }

private:
    const ShiftedFactor& mFactor;
    const Eigen::MatrixXd& mDeflated;
};

/// The `nev` lowest pairs of the (deflated) operator: ascending values, scaled vectors.
EigenPairs lanczos(const ShiftedFactor& factor, const Eigen::MatrixXd& deflated, Eigen::Index nev,
                   const EigenRequest& request, long& restarts) {
    const Eigen::Index n = factor.size();
    ScaledShiftInvert op(factor, deflated);
    // ncv = 1.5 nev needed fewer solves and less time than the textbook 2 nev (tools/README.md,
    // "Precompute speed"): the Krylov basis is re-orthogonalized at every step, and its bandwidth
    // grows with ncv.
    const Eigen::Index room = n - deflated.cols();
    const Eigen::Index ncv =
        std::min<Eigen::Index>(room, std::max<Eigen::Index>(3 * nev / 2 + 1, nev + 30));
    Spectra::SymEigsShiftSolver<ScaledShiftInvert> solver(op, nev, ncv, request.shift);
    try {
        if (deflated.cols() == 0) {
            solver.init();
        } else {
            // A start vector with no part along the pairs already found (a fixed seed: repeatable).
            std::mt19937_64 random(0x5eed);
            std::uniform_real_distribution<double> uniform(-0.5, 0.5);
            Eigen::VectorXd start(n);
            for (Eigen::Index i = 0; i < n; ++i) start[i] = uniform(random);
            start = op.project(start);
            solver.init(start.data());
        }
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
    restarts += solver.num_iterations();
    if (solver.info() != Spectra::CompInfo::Successful)
        throw Error(request.what + ": Lanczos did not converge for " + std::to_string(nev) +
                    " eigenpairs (" + std::to_string(solver.num_iterations()) + " restarts)");
    EigenPairs out;
    out.values = solver.eigenvalues();
    out.vectors = solver.eigenvectors();
    return out;
}

/// The `nev` lowest pairs of the (deflated) operator in blocks (BlockLanczos.h): ascending values,
/// scaled vectors.
EigenPairs blockLanczos(const ShiftedFactor& factor, const Eigen::MatrixXd& deflated,
                        Eigen::Index nev, const EigenRequest& request, long& restarts) {
    BlockLanczosRequest block;
    block.count = nev;
    block.tolerance = request.tolerance;
    block.what = request.what;
    const BlockLanczosResult found =
        largestEigenpairs([&](const Eigen::Ref<const Eigen::MatrixXd>& x,
                              Eigen::Ref<Eigen::MatrixXd> y) { factor.apply(x, y); },
                          factor.size(), deflated, block);
    restarts += found.restarts;
    // θ = 1/(λ − σ): the largest θ are the lowest λ, in order.
    EigenPairs out;
    out.values = (request.shift + found.values.array().inverse()).matrix();
    out.vectors = found.vectors;
    return out;
}

/// The `keep` lowest of two sets of pairs together, ascending.
EigenPairs lowestOf(const EigenPairs& a, const EigenPairs& b, Eigen::Index keep) {
    const Eigen::Index total = a.values.size() + b.values.size();
    std::vector<Eigen::Index> order(static_cast<std::size_t>(total));
    std::iota(order.begin(), order.end(), 0);
    const auto value = [&](Eigen::Index i) {
        return i < a.values.size() ? a.values[i] : b.values[i - a.values.size()];
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](Eigen::Index i, Eigen::Index j) { return value(i) < value(j); });
    EigenPairs out;
    out.values.resize(keep);
    out.vectors.resize(a.vectors.rows(), keep);
    for (Eigen::Index c = 0; c < keep; ++c) {
        const Eigen::Index i = order[std::size_t(c)];
        out.values[c] = value(i);
        out.vectors.col(c) =
            i < a.values.size() ? a.vectors.col(i) : b.vectors.col(i - a.values.size());
    }
    return out;
}

/// Runs on the operator deflated by the pairs kept so far, while they find eigenvalues below the
/// highest kept one: copies of degenerate eigenvalues that the first run missed.
using KrylovRun = EigenPairs (*)(const ShiftedFactor&, const Eigen::MatrixXd&, Eigen::Index,
                                 const EigenRequest&, long&);

void findMissedCopies(const ShiftedFactor& factor, EigenPairs& pairs, const EigenRequest& request,
                      KrylovRun run, long& restarts) {
    const Eigen::Index nev = pairs.values.size();
    constexpr int kMaxRuns = 32;
    for (int rerun = 0;; ++rerun) {
        const Eigen::Index block =
            std::min<Eigen::Index>(std::max<Eigen::Index>(8, nev / 4), factor.size() - nev - 2);
        if (block < 1) return;
        const double top = pairs.values[nev - 1];
        const EigenPairs more = run(factor, pairs.vectors, block, request, restarts);
        // Equal to the highest kept one is no miss: a cut through a degenerate eigenspace keeps
        // any part of it.
        if (more.values[0] >= top - 1e-9 * std::abs(top)) return;
        if (rerun == kMaxRuns)
            throw Error(request.what +
                        ": still finding missed copies of degenerate eigenvalues after " +
                        std::to_string(kMaxRuns) + " deflated Lanczos runs");
        pairs = lowestOf(pairs, more, nev);
    }
}

/// The most of the ascending `values` equal to round-off. Copies mean symmetries: a Lanczos run
/// may have missed some, and a block run more copies than half its block.
Eigen::Index largestMultiplicity(const Eigen::VectorXd& values) {
    Eigen::Index most = values.size() > 0 ? 1 : 0, copies = 1;
    for (Eigen::Index i = 1; i < values.size(); ++i) {
        copies = values[i] - values[i - 1] <= 1e-9 * std::abs(values[i]) ? copies + 1 : 1;
        most = std::max(most, copies);
    }
    return most;
}

}  // namespace

EigenPairs smallestEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                              const Eigen::VectorXd& massDiagonal, const EigenRequest& request,
                              KrylovMethod method) {
    const Eigen::Index n = stiffness.rows();
    if (request.count < 1 || request.count >= n)
        throw Error(request.what + ": asked for " + std::to_string(request.count) +
                    " eigenpairs of a " + std::to_string(n) + "-dimensional space");
    SolverStats stats;
    const ShiftedFactor factor(stiffness, massDiagonal, request.shift, request, stats);
    long restarts = 0;
    const bool blocks = method == KrylovMethod::BlockLanczos;
    const KrylovRun run = blocks ? blockLanczos : lanczos;
    EigenPairs out = run(factor, Eigen::MatrixXd(n, 0), request.count, request, restarts);
    const Eigen::Index copies = largestMultiplicity(out.values);
    if (blocks ? 2 * copies >= BlockLanczosRequest{}.blockSize
               : request.findMissedCopies || copies > 1)
        findMissedCopies(factor, out, request, run, restarts);
    out.vectors = factor.scale().cwiseInverse().asDiagonal() * out.vectors;
    out.stats = stats;
    out.stats.restarts = restarts;
    return out;
}

}  // namespace modeflow
