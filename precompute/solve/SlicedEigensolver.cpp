#include "precompute/solve/SlicedEigensolver.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "precompute/solve/PetscRuntime.h"
#include "precompute/solve/ProcessGroup.h"
#include "precompute/solve/SliceCheckpoint.h"

namespace modeflow {
namespace {

/// Ascending order of the pairs (SLEPc gives each subinterval's in order, but not across them).
void sortAscending(EigenPairs& pairs) {
    std::vector<Eigen::Index> order(size_t(pairs.values.size()));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
        return pairs.values[a] < pairs.values[b];
    });
    EigenPairs sorted;
    sorted.values.resize(pairs.values.size());
    sorted.vectors.resize(pairs.vectors.rows(), pairs.vectors.cols());
    for (size_t c = 0; c < order.size(); ++c) {
        sorted.values[Eigen::Index(c)] = pairs.values[order[c]];
        sorted.vectors.col(Eigen::Index(c)) = pairs.vectors.col(order[c]);
    }
    pairs.values = std::move(sorted.values);
    pairs.vectors = std::move(sorted.vectors);
}

/// What K x − λ M x may hold of λ's scale before a pair is refused (SLEPc's converged pairs hold
/// about 1e-12 of it; wrong ones, tenths).
constexpr double kResidualLimit = 1e-6;

/// Whether every pair solves K x = λ M x, λ in [lo, hi]. SLEPc trusts the factorizations'
/// inertia, and MUMPS's LDLᵀ at a shift on a multiple eigenvalue can miscount without failing:
/// with single-threaded BLAS a 16-fold eigenvalue on an interval's end came back as eigenvalues
/// up to 30% off, as converged. Norms in M⁻¹ (the residual) and M (the vector).
bool pairsSolveTheProblem(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                          const EigenPairs& pairs, double lo, double hi) {
    const double scale = std::max(std::abs(lo), std::abs(hi));
    const Eigen::MatrixXd residual =
        k * pairs.vectors - m.asDiagonal() * pairs.vectors * pairs.values.asDiagonal();
    const Eigen::VectorXd root = m.cwiseSqrt(), inverseRoot = root.cwiseInverse();
    for (Eigen::Index i = 0; i < pairs.values.size(); ++i) {
        const double value = pairs.values[i];
        const double r = inverseRoot.cwiseProduct(residual.col(i)).norm();
        const double x = root.cwiseProduct(pairs.vectors.col(i)).norm();
        if (!(value >= lo && value <= hi && r <= kResidualLimit * scale * x)) return false;
    }
    return true;
}

/// Where the next interval ends so that, with N(λ) = c λ^{d/2} fitted to `found` eigenvalues
/// below `end`, it holds the `wanted` − `found` still missing (and a few more: the law is only
/// asymptotic, and another interval costs its end factorizations again).
double nextEnd(double end, long found, long wanted, int dimension) {
    if (found == 0) return 4.0 * end;
    const double ratio = (1.05 * double(wanted) + 2.0) / double(found);
    return end * std::max(1.1, std::pow(ratio, 2.0 / dimension));
}

/// Interval `index` of the solve, starting at `lo`, as an interrupted run kept it: read by rank 0
/// and sent to every rank, so that all resume the same intervals. Nothing when there is none, or
/// when it cannot be trusted (damaged, foreign: said through the request's note).
std::optional<SliceCheckpoint> resumedInterval(const EigenRequest& request, std::uint64_t problem,
                                               int index, double lo, Eigen::Index rows) {
    const IntervalCheckpoints& place = request.checkpoints;
    if (place.cachePath.empty()) return std::nullopt;
    std::optional<SliceCheckpoint> stored;
    if (currentProcessGroup().primary()) {
        const std::filesystem::path path = sliceCheckpointPath(place.cachePath, problem, index);
        std::error_code ec;
        if (std::filesystem::exists(path, ec)) try {
                stored = readSliceCheckpoint(path, problem, index, lo, rows);
            } catch (const Error& e) {
                if (place.note) place.note(request.what + ": " + e.what() + "; solving it again");
            }
    }
    if (currentProcessGroup().size == 1) return stored;
    PetscRuntime& ranks = petscRuntime();
    long count = stored ? long(stored->values.size()) : -1;
    ranks.broadcast(count);
    if (count < 0) return std::nullopt;
    if (!stored) {
        stored.emplace();
        stored->problem = problem;
        stored->interval = index;
        stored->lo = lo;
        stored->values.resize(count);
        stored->vectors.resize(rows, count);
    }
    ranks.broadcast(&stored->hi, 1);
    ranks.broadcast(stored->values.data(), count);
    ranks.broadcast(stored->vectors.data(), stored->vectors.size());
    return stored;
}

/// Keeps a solved interval for a rerun (rank 0 writes it). A checkpoint that cannot be written
/// costs only the resumption: the solve goes on, and says so.
void keepInterval(const EigenRequest& request, const SliceCheckpoint& interval) {
    const IntervalCheckpoints& place = request.checkpoints;
    if (place.cachePath.empty() || !currentProcessGroup().primary()) return;
    try {
        writeSliceCheckpoint(
            sliceCheckpointPath(place.cachePath, interval.problem, interval.interval), interval);
    } catch (const Error& e) {
        if (place.note) place.note(request.what + ": " + e.what() + "; going on without it");
    }
}

/// A test hook (tests/tools/PrecomputeResumeTest.cpp): with MODEFLOW_TEST_STOP_AFTER_INTERVALS=k
/// the process fails once it has solved and kept k intervals, as a precompute killed there.
void stopWhereATestAsks(const EigenRequest& request) {
    static long solved = 0;
    ++solved;
    const char* limit = std::getenv("MODEFLOW_TEST_STOP_AFTER_INTERVALS");
    if (limit != nullptr && solved >= std::atol(limit))
        throw Error(request.what + ": stopped after " + std::to_string(solved) +
                    " intervals, as MODEFLOW_TEST_STOP_AFTER_INTERVALS asks");
}

}  // namespace

std::vector<double> weylSubintervals(double lo, double hi, int parts, int dimension) {
    const double exponent = dimension / 2.0;
    const double first = std::pow(std::max(lo, 0.0), exponent), last = std::pow(hi, exponent);
    std::vector<double> ends(size_t(parts) + 1);
    ends.front() = lo;
    for (int p = 1; p < parts; ++p)
        ends[size_t(p)] = std::pow(first + (last - first) * p / parts, 1.0 / exponent);
    ends.back() = hi;
    return ends;
}

EigenPairs slicedEigenpairs(const Eigen::SparseMatrix<double>& stiffness,
                            const Eigen::VectorXd& massDiagonal, const EigenRequest& request) {
    const Eigen::Index n = stiffness.rows();
    if (request.count < 1 || request.count >= n)
        throw Error(request.what + ": asked for " + std::to_string(request.count) +
                    " eigenpairs of a " + std::to_string(n) + "-dimensional space");
    if (!(request.estimate > 0.0))
        throw Error(request.what +
                    ": the sliced eigensolver needs an estimate of the highest "
                    "wanted eigenvalue");
    Eigen::SparseMatrix<double> k = stiffness;
    k.makeCompressed();
    const std::unique_ptr<DistributedEigenproblem> problem =
        petscRuntime().distribute(k, massDiagonal, request);
    const int parts = currentProcessGroup().partitions;
    // The partitions' subintervals, equally full by Weyl's law.
    const auto ends = [&](double a, double b) {
        return parts > 1 ? weylSubintervals(a, b, parts, request.spectralDimension)
                         : std::vector<double>();
    };

    const std::uint64_t problemHash =
        request.checkpoints.cachePath.empty() ? 0 : sliceProblemHash(k, massDiagonal, request);
    std::vector<SliceCheckpoint> intervals;
    long found = 0;
    int resumed = 0;
    double lo = request.shift, hi = 1.02 * request.estimate;
    EigenPairs out;
    constexpr int kMaxIntervals = 64;
    for (int interval = 0; found < request.count; ++interval) {
        if (interval == kMaxIntervals)
            throw Error(request.what + ": " + std::to_string(kMaxIntervals) +
                        " intervals of the spectrum held only " + std::to_string(found) + " of " +
                        std::to_string(request.count) + " eigenvalues");
        if (std::optional<SliceCheckpoint> stored =
                resumedInterval(request, problemHash, interval, lo, n)) {
            // Its end may be one moved off an eigenvalue (below): the sequence goes on from it.
            hi = stored->hi;
            intervals.push_back(std::move(*stored));
            ++resumed;
        } else {
            // An eigenvalue on the upper end (the lower one is the last interval's end, which was
            // not singular) or on a shift: a slightly higher end, the next attempt.
            const auto solve = [&] {
                std::optional<EigenPairs> found =
                    problem->solveInterval(lo, hi, ends(lo, hi), out.stats);
                if (found && !pairsSolveTheProblem(k, massDiagonal, *found, lo, hi)) found.reset();
                return found;
            };
            std::optional<EigenPairs> pairs = solve();
            for (int attempt = 0; !pairs; ++attempt) {
                if (attempt == 3)
                    throw Error(request.what +
                                ": the factorizations stayed singular or miscounted with every "
                                "interval end tried near " +
                                std::to_string(hi) + " (" + lastPetscErrorMessage() + ")");
                hi += 1e-6 * (hi - lo);
                pairs = solve();
            }
            intervals.push_back({problemHash, interval, lo, hi, std::move(pairs->values),
                                 std::move(pairs->vectors)});
            keepInterval(request, intervals.back());
            stopWhereATestAsks(request);
        }
        found += long(intervals.back().values.size());
        lo = hi;
        hi = nextEnd(hi, found, request.count, request.spectralDimension);
    }
    if (resumed > 0 && request.checkpoints.note)
        request.checkpoints.note(request.what + ": " + std::to_string(resumed) + " of " +
                                 std::to_string(intervals.size()) +
                                 " intervals from an interrupted run");
    out.values.resize(found);
    out.vectors.resize(n, found);
    Eigen::Index column = 0;
    for (const SliceCheckpoint& pairs : intervals) {
        const Eigen::Index c = pairs.values.size();
        out.values.segment(column, c) = pairs.values;
        out.vectors.middleCols(column, c) = pairs.vectors;
        column += c;
    }
    sortAscending(out);
    out.values.conservativeResize(request.count);
    out.vectors.conservativeResize(Eigen::NoChange, request.count);
    return out;
}

}  // namespace modeflow
