#include "precompute/solve/ShiftInvertEigensolver.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <new>
#include <numeric>
#include <random>
#include <vector>

#include <omp.h>

#include <Spectra/SymEigsShiftSolver.h>
#include <Eigen/CholmodSupport>

#include "engine/core/Error.h"
#include "precompute/solve/BlasThreads.h"
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

/// What one CHOLMOD solve of the factor writes to: its own cholmod_common (status and scratch),
/// so that several solves run at once, and its arrays, kept from one solve to the next (a fresh
/// block-sized array costs its page faults every time).
class SolveWorkspace {
public:
    SolveWorkspace() {
        cholmod_start(&mCommon);
        mCommon.print = 0;  // CHOLMOD prints on stdout; its status becomes our message instead
    }
    ~SolveWorkspace() {
        for (cholmod_dense** d : {&mSolution, &mWork, &mWorkE}) cholmod_free_dense(d, &mCommon);
        cholmod_finish(&mCommon);
    }
    SolveWorkspace(const SolveWorkspace&) = delete;
    SolveWorkspace& operator=(const SolveWorkspace&) = delete;

    /// The solution X of (K − σM) X = B in CHOLMOD's array, or nullptr when CHOLMOD's status
    /// (common()) says it failed.
    const double* solve(cholmod_factor* factor, Eigen::Ref<Eigen::MatrixXd> b) {
        cholmod_dense right = Eigen::viewAsCholmod(b);
        cholmod_solve2(CHOLMOD_A, factor, &right, nullptr, &mSolution, nullptr, &mWork, &mWorkE,
                       &mCommon);
        return mCommon.status == CHOLMOD_OK ? static_cast<const double*>(mSolution->x) : nullptr;
    }
    const cholmod_common& common() const { return mCommon; }

private:
    cholmod_common mCommon;
    cholmod_dense* mSolution = nullptr;
    cholmod_dense* mWork = nullptr;
    cholmod_dense* mWorkE = nullptr;
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
        // A block's columns are solved in as many parts at once as OpenMP has threads, each with
        // one BLAS thread: CHOLMOD's supernodal solve calls BLAS on pieces too small for
        // OpenBLAS's threads to gain anything (measured on the seed's sphere scene: 25.6 s of
        // solves with one BLAS thread, 28.0 s with two), while two parts at once took 20.6 s.
        const int parts = BlasThreads::controllable() ? std::max(1, omp_get_max_threads()) : 1;
        for (int p = 0; p < parts; ++p) mWorkspaces.push_back(std::make_unique<SolveWorkspace>());
    }

    ShiftedFactor(const ShiftedFactor&) = delete;
    ShiftedFactor& operator=(const ShiftedFactor&) = delete;

    Eigen::Index size() const { return mScale.size(); }
    /// M^{1/2} diagonal: scaled vectors are M^{1/2} x.
    const Eigen::VectorXd& scale() const { return mScale; }

    /// y = M^{1/2} (K − σM)⁻¹ M^{1/2} x, for one vector or a block of them (CHOLMOD solves
    /// with several right-hand sides: its supernodal solve runs BLAS-3 on them).
    void apply(const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::Ref<Eigen::MatrixXd> y) const {
        const auto start = std::chrono::steady_clock::now();
        mRight.noalias() = mScale.asDiagonal() * x;
        const auto parts = int(std::min<Eigen::Index>(Eigen::Index(mWorkspaces.size()), x.cols()));
        const auto solvePart = [&](int p) {
            const Eigen::Index first = x.cols() * p / parts,
                               count = x.cols() * (p + 1) / parts - first;
            SolveWorkspace& workspace = *mWorkspaces[std::size_t(p)];
            const double* solution =
                workspace.solve(mSolver.factor(), mRight.middleCols(first, count));
            if (solution)
                y.middleCols(first, count).noalias() =
                    mScale.asDiagonal() *
                    Eigen::Map<const Eigen::MatrixXd>(solution, x.rows(), count);
        };
        if (parts == 1) {
            solvePart(0);
        } else {
            const BlasThreads oneEach(1);
#pragma omp parallel for num_threads(parts) schedule(static, 1)
            for (int p = 0; p < parts; ++p) solvePart(p);
        }
        for (int p = 0; p < parts; ++p)
            requireCholmodSuccess(mWorkspaces[std::size_t(p)]->common(), mRequest.what, size());
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
    std::vector<std::unique_ptr<SolveWorkspace>> mWorkspaces;  ///< one per part solved at once
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
