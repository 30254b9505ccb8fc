#include "precompute/solve/SlicedEigensolver.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <string>

#include <slepceps.h>

#include "engine/core/Error.h"
#include "engine/core/LibraryLeaks.h"
#include "precompute/solve/ProcessGroup.h"
#include "precompute/solve/SliceCheckpoint.h"

namespace modeflow {
namespace {

/// PETSc's status as our error naming the solve and the call.
void check(PetscErrorCode code, const EigenRequest& request, const char* call) {
    if (code == 0) return;
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    std::string detail = text != nullptr ? std::string(text) : "error " + std::to_string(code);
    if (const std::string where = lastPetscErrorMessage(); !where.empty()) detail += ": " + where;
    throw Error(request.what + ": " + call + " failed (PETSc: " + detail + ")");
}

/// Owns one PETSc object.
template <class T, PetscErrorCode (*Destroy)(T*)>
class Owned {
public:
    Owned() = default;
    Owned(const Owned&) = delete;
    Owned& operator=(const Owned&) = delete;
    ~Owned() {
        if (mObject != nullptr) Destroy(&mObject);
    }
    T* out() { return &mObject; }
    T get() const { return mObject; }

private:
    T mObject = nullptr;
};
using OwnedMat = Owned<Mat, MatDestroy>;
using OwnedVec = Owned<Vec, VecDestroy>;
using OwnedEps = Owned<EPS, EPSDestroy>;
using OwnedScatter = Owned<VecScatter, VecScatterDestroy>;

/// Count and seconds of one PETSc event so far in this process (its log is on: ensureLogging).
struct EventTally {
    long count = 0;
    double seconds = 0.0;
};

EventTally tally(const char* event) {
    PetscLogEvent id = -1;
    PetscEventPerfInfo info{};
    // An event not registered yet (KSPSolve before the first KSP) has id −1, without an error.
    if (PetscLogEventGetId(event, &id) != 0 || id < 0 ||
        PetscLogEventGetPerfInfo(0, id, &info) != 0)
        return {};
    return {long(info.count), info.time};
}

/// Factorizations and solves counted by PETSc's log, for SolverStats and progress lines.
struct Tallies {
    EventTally factor = tally("MatCholFctrNum");
    EventTally solve = tally("KSPSolve");
};

void ensureLogging() {
    static const bool started = [] { return PetscLogDefaultBegin() == 0; }();
    (void)started;
}

/// The slicing's inner eigensolver configures its shift-invert solves from the options database
/// (prefix st_), not from the outer solver's objects: MUMPS's LDLᵀ (PETSc's own Cholesky has no
/// fill-reducing ordering: 10× slower on a 32³ ball) and, across ranks, its parallel inertia
/// (ICNTL 13). What a user set in PETSC_OPTIONS stays.
void setFactorizationDefaults() {
    const std::pair<const char*, const char*> defaults[] = {
        {"-st_ksp_type", "preonly"},
        {"-st_pc_type", "cholesky"},
        {"-st_pc_factor_mat_solver_type", "mumps"},
        {"-st_mat_mumps_icntl_13", "1"}};
    for (const auto& [name, value] : defaults) {
        PetscBool set = PETSC_FALSE;
        PetscOptionsHasName(nullptr, nullptr, name, &set);
        if (!set) PetscOptionsSetValue(nullptr, name, value);
    }
}

/// K (symmetric: its columns are its rows) and diag(M) as PETSc matrices distributed by rows
/// over every rank.
class DistributedProblem {
public:
    DistributedProblem(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                       const EigenRequest& request) {
        const PetscInt n = PetscInt(k.rows());
        PetscInt local = PETSC_DECIDE, total = n;
        check(PetscSplitOwnership(PETSC_COMM_WORLD, &local, &total), request,
              "PetscSplitOwnership");
        PetscInt end = 0;
        MPI_Scan(&local, &end, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
        const PetscInt begin = end - local;

        std::vector<PetscInt> diagonal(size_t(local), 0), offDiagonal(size_t(local), 0);
        for (PetscInt r = begin; r < end; ++r)
            for (Eigen::SparseMatrix<double>::InnerIterator it(k, r); it; ++it)
                ++(it.row() >= begin && it.row() < end ? diagonal : offDiagonal)[size_t(r - begin)];
        check(MatCreateAIJ(PETSC_COMM_WORLD, local, local, n, n, 0, diagonal.data(), 0,
                           offDiagonal.data(), mStiffness.out()),
              request, "MatCreateAIJ");
        std::vector<PetscInt> columns;
        std::vector<PetscScalar> values;
        for (PetscInt r = begin; r < end; ++r) {
            columns.clear();
            values.clear();
            for (Eigen::SparseMatrix<double>::InnerIterator it(k, r); it; ++it) {
                columns.push_back(PetscInt(it.row()));
                values.push_back(it.value());
            }
            check(MatSetValues(mStiffness.get(), 1, &r, PetscInt(columns.size()), columns.data(),
                               values.data(), INSERT_VALUES),
                  request, "MatSetValues");
        }
        check(
            MatCreateAIJ(PETSC_COMM_WORLD, local, local, n, n, 1, nullptr, 0, nullptr, mMass.out()),
            request, "MatCreateAIJ");
        for (PetscInt r = begin; r < end; ++r)
            check(MatSetValue(mMass.get(), r, r, m[r], INSERT_VALUES), request, "MatSetValue");
        for (Mat a : {mStiffness.get(), mMass.get()}) {
            check(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY), request, "MatAssemblyBegin");
            check(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY), request, "MatAssemblyEnd");
            check(MatSetOption(a, MAT_SYMMETRIC, PETSC_TRUE), request, "MatSetOption");
            check(MatSetOption(a, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), request, "MatSetOption");
        }
    }

    Mat stiffness() const { return mStiffness.get(); }
    Mat mass() const { return mMass.get(); }

private:
    OwnedMat mStiffness, mMass;
};

/// Counts the shift-invert solves of the slicing's inner eigensolver for the progress line (its
/// restarts are not reported to the outer solver's monitors).
struct SolveCounter {
    const EigenRequest* request = nullptr;
    long solves = 0;
};

PetscErrorCode afterSolve(KSP, Vec, Vec, void* context) {
    auto& c = *static_cast<SolveCounter*>(context);
    if (++c.solves % 16 == 0) c.request->progress(c.solves);
    return 0;
}

/// Krylov–Schur eigenvalues of the pairs found per shift: SLEPc's advice for slicing is a few
/// dozen; larger values mean fewer factorizations but longer Krylov bases per shift.
constexpr PetscInt kPairsPerShift = 40;

/// Whether a failed factorization or count says that a shift lies on an eigenvalue: MUMPS's LDLᵀ
/// then either fails (a zero pivot) or gives an inertia that disagrees with the eigenvalues found.
bool onEigenvalue(PetscErrorCode code) {
    return code == PETSC_ERR_MAT_LU_ZRPVT || code == PETSC_ERR_PLIB;
}

/// Every eigenpair in [lo, hi), vectors M-orthonormal, on every rank; nothing when a shift lies on
/// an eigenvalue (the caller moves the interval's end, which SLEPc's shifts follow).
std::optional<EigenPairs> solveInterval(const DistributedProblem& problem, double lo, double hi,
                                        const EigenRequest& request, SolverStats& stats) {
    const Tallies before;
    const int parts = currentProcessGroup().partitions;
    OwnedEps eps;
    check(EPSCreate(PETSC_COMM_WORLD, eps.out()), request, "EPSCreate");
    EPS e = eps.get();
    check(EPSSetOperators(e, problem.stiffness(), problem.mass()), request, "EPSSetOperators");
    check(EPSSetProblemType(e, EPS_GHEP), request, "EPSSetProblemType");
    check(EPSSetType(e, EPSKRYLOVSCHUR), request, "EPSSetType");
    check(EPSSetWhichEigenpairs(e, EPS_ALL), request, "EPSSetWhichEigenpairs");
    check(EPSSetInterval(e, lo, hi), request, "EPSSetInterval");
    check(EPSSetTolerances(e, request.tolerance, 1000), request, "EPSSetTolerances");
    // Purification (one more solve per vector, for a singular M) costs M-orthogonality here: 4e-9
    // between distinct eigenvalues with it, 4e-11 without; M is diagonal and positive.
    check(EPSSetPurify(e, PETSC_FALSE), request, "EPSSetPurify");
    ST st = nullptr;
    check(EPSGetST(e, &st), request, "EPSGetST");
    check(STSetType(st, STSINVERT), request, "STSetType");
    check(EPSKrylovSchurSetPartitions(e, parts), request, "EPSKrylovSchurSetPartitions");
    if (parts > 1) {
        std::vector<double> ends = weylSubintervals(lo, hi, parts, request.spectralDimension);
        check(EPSKrylovSchurSetSubintervals(e, ends.data()), request,
              "EPSKrylovSchurSetSubintervals");
    }
    check(EPSKrylovSchurSetDimensions(e, kPairsPerShift, PETSC_DEFAULT, PETSC_DEFAULT), request,
          "EPSKrylovSchurSetDimensions");
    // Last: the slicing's inner solver takes its factorization (MUMPS, setFactorizationDefaults)
    // from the options database only, and users tune it there (PETSC_OPTIONS).
    check(EPSSetFromOptions(e), request, "EPSSetFromOptions");
    // The set-up factorizes at the interval's ends (their inertia), the solve at its shifts.
    const PetscErrorCode setUp = EPSSetUp(e);
    if (onEigenvalue(setUp)) return std::nullopt;
    check(setUp, request, "EPSSetUp");
    SolveCounter counter{&request, stats.operations};
    if (request.progress) {
        KSP inner = nullptr;
        check(EPSKrylovSchurGetKSP(e, &inner), request, "EPSKrylovSchurGetKSP");
        check(KSPSetPostSolve(inner, afterSolve, &counter), request, "KSPSetPostSolve");
    }
    const PetscErrorCode solved = [e] {
        [[maybe_unused]] const IgnoreLibraryLeaks ignore;  // SLEPc's own, on clustered ends
        return EPSSolve(e);
    }();
    if (onEigenvalue(solved)) return std::nullopt;
    check(solved, request, "the sliced eigensolve (EPSSolve)");

    PetscInt converged = 0, restarts = 0;
    check(EPSGetConverged(e, &converged), request, "EPSGetConverged");
    check(EPSGetIterationNumber(e, &restarts), request, "EPSGetIterationNumber");
    stats.restarts += restarts;
    PetscInt rows = 0;
    check(MatGetSize(problem.stiffness(), &rows, nullptr), request, "MatGetSize");
    EigenPairs out;
    out.values.resize(converged);
    out.vectors.resize(rows, converged);
    OwnedVec x, whole;
    check(MatCreateVecs(problem.stiffness(), x.out(), nullptr), request, "MatCreateVecs");
    OwnedScatter toAll;
    check(VecScatterCreateToAll(x.get(), toAll.out(), whole.out()), request,
          "VecScatterCreateToAll");
    for (PetscInt i = 0; i < converged; ++i) {
        PetscScalar value = 0.0;
        check(EPSGetEigenpair(e, i, &value, nullptr, x.get(), nullptr), request, "EPSGetEigenpair");
        check(VecScatterBegin(toAll.get(), x.get(), whole.get(), INSERT_VALUES, SCATTER_FORWARD),
              request, "VecScatterBegin");
        check(VecScatterEnd(toAll.get(), x.get(), whole.get(), INSERT_VALUES, SCATTER_FORWARD),
              request, "VecScatterEnd");
        const PetscScalar* data = nullptr;
        check(VecGetArrayRead(whole.get(), &data), request, "VecGetArrayRead");
        out.values[i] = value;
        out.vectors.col(i) = Eigen::Map<const Eigen::VectorXd>(data, rows);
        check(VecRestoreArrayRead(whole.get(), &data), request, "VecRestoreArrayRead");
    }
    const Tallies after;
    stats.factorizations += after.factor.count - before.factor.count;
    stats.factorSeconds += after.factor.seconds - before.factor.seconds;
    stats.operations += after.solve.count - before.solve.count;
    stats.solveSeconds += after.solve.seconds - before.solve.seconds;
    return out;
}

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
    long count = stored ? long(stored->values.size()) : -1;
    MPI_Bcast(&count, 1, MPI_LONG, 0, PETSC_COMM_WORLD);
    if (count < 0) return std::nullopt;
    if (!stored) {
        stored.emplace();
        stored->problem = problem;
        stored->interval = index;
        stored->lo = lo;
        stored->values.resize(count);
        stored->vectors.resize(rows, count);
    }
    MPI_Bcast(&stored->hi, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
    MPI_Bcast(stored->values.data(), int(count), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
    // Column by column: a whole interval's vectors can exceed MPI's int count.
    for (Eigen::Index c = 0; c < count; ++c)
        MPI_Bcast(stored->vectors.col(c).data(), int(rows), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
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
    ensurePetsc();
    ensureLogging();
    static const bool defaults = (setFactorizationDefaults(), true);
    (void)defaults;
    Eigen::SparseMatrix<double> k = stiffness;
    k.makeCompressed();
    const DistributedProblem problem(k, massDiagonal, request);

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
            std::optional<EigenPairs> pairs = solveInterval(problem, lo, hi, request, out.stats);
            // An eigenvalue on the upper end (the lower one is the last interval's end, which was
            // not singular) or on a shift: a slightly higher end, the next attempt.
            for (int attempt = 0; !pairs; ++attempt) {
                if (attempt == 3)
                    throw Error(request.what +
                                ": the factorizations stayed singular or miscounted with every "
                                "interval end tried near " +
                                std::to_string(hi) + " (" + lastPetscErrorMessage() + ")");
                hi += 1e-6 * (hi - lo);
                pairs = solveInterval(problem, lo, hi, request, out.stats);
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
