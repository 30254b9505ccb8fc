/// @file PetscModule.cpp
/// The PETSc, SLEPc and MPI side of the sliced eigensolver (precompute/solve/PetscRuntime.h),
/// built as a module of its own (libmodeflow_petsc.so) and loaded on first use: the one place in
/// the project that includes their headers or links them.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <slepceps.h>

#include "engine/core/Error.h"
#include "engine/core/LibraryLeaks.h"
#include "precompute/solve/PetscRuntime.h"

namespace modeflow {
namespace {

/// The innermost message of the error PETSc is returning (where it was raised: later frames of
/// the same error add none), for our own error line.
std::string& petscMessage() {
    static std::string message;
    return message;
}

PetscErrorCode keepMessage(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                           PetscErrorType type, const char* message, void*) {
    if (type == PETSC_ERROR_INITIAL) petscMessage() = message != nullptr ? message : "";
    return code;
}

void finalizePetsc() {
    PetscBool finalized = PETSC_FALSE;
    if (PetscFinalized(&finalized) == 0 && !finalized) {
        [[maybe_unused]] const IgnoreLibraryLeaks ignore;  // Open MPI keeps ~120 KB
        SlepcFinalize();
    }
}

/// PETSc's status as our error naming the solve and the call.
void check(PetscErrorCode code, const EigenRequest& request, const char* call) {
    if (code == 0) return;
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    std::string detail = text != nullptr ? std::string(text) : "error " + std::to_string(code);
    if (const std::string& where = petscMessage(); !where.empty()) detail += ": " + where;
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
/// fill-reducing ordering and was far slower: precompute/README.md) and, across ranks, its
/// parallel inertia (ICNTL 13). What a user set in PETSC_OPTIONS stays.
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
                                        const std::vector<double>& subintervals,
                                        const EigenRequest& request, SolverStats& stats) {
    const Tallies before;
    const int parts = subintervals.empty() ? 1 : int(subintervals.size()) - 1;
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
        std::vector<double> ends = subintervals;
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

class Runtime final : public PetscRuntime {
public:
    void start() override { ensurePetsc(); }
    bool started() const override {
        PetscBool initialized = PETSC_FALSE;
        SlepcInitialized(&initialized);
        return initialized == PETSC_TRUE;
    }
    ProcessGroup group() const override { return currentProcessGroup(); }
    std::string lastError() const override { return petscMessage(); }
    std::unique_ptr<DistributedEigenproblem> distribute(
        const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& massDiagonal,
        const EigenRequest& request) override;
    void broadcast(long& value) override { MPI_Bcast(&value, 1, MPI_LONG, 0, PETSC_COMM_WORLD); }
    void broadcast(double* values, Eigen::Index count) override {
        // In pieces: a whole interval's vectors can exceed MPI's int count.
        constexpr Eigen::Index kPiece = Eigen::Index(1) << 30;
        for (Eigen::Index at = 0; at < count; at += kPiece)
            MPI_Bcast(values + at, int(std::min(kPiece, count - at)), MPI_DOUBLE, 0,
                      PETSC_COMM_WORLD);
    }

private:
    static void ensurePetsc();
    static ProcessGroup currentProcessGroup();
};

class Problem final : public DistributedEigenproblem {
public:
    Problem(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
            const EigenRequest& request)
        : mRequest(request), mProblem(k, m, request) {}
    std::optional<EigenPairs> solveInterval(double lo, double hi, const std::vector<double>& ends,
                                            SolverStats& stats) override {
        return modeflow::solveInterval(mProblem, lo, hi, ends, mRequest, stats);
    }

private:
    const EigenRequest& mRequest;
    DistributedProblem mProblem;
};

}  // namespace

void Runtime::ensurePetsc() {
    PetscBool initialized = PETSC_FALSE;
    SlepcInitialized(&initialized);
    if (initialized) return;
    // Our own signal handlers and error messages stay in charge: PETSc's would print tracebacks
    // and catch Ctrl-C.
    PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
    const PetscErrorCode started = [] {
        [[maybe_unused]] const IgnoreLibraryLeaks ignore;  // Open MPI keeps ~120 KB
        return SlepcInitializeNoArguments();
    }();
    if (started != 0)
        throw Error(
            "precompute: MPI and PETSc could not be initialized (SLEPc's eigensolver needs "
            "them; under mpirun, check the launcher's own messages)");
    PetscPushErrorHandler(keepMessage, nullptr);
    std::atexit(finalizePetsc);
}

ProcessGroup Runtime::currentProcessGroup() {
    PetscBool initialized = PETSC_FALSE;
    SlepcInitialized(&initialized);
    if (!initialized) return {};
    ProcessGroup group;
    MPI_Comm_rank(PETSC_COMM_WORLD, &group.rank);
    MPI_Comm_size(PETSC_COMM_WORLD, &group.size);
    PetscInt partitions = group.size;
    PetscBool set = PETSC_FALSE;
    PetscOptionsGetInt(nullptr, nullptr, "-eps_krylovschur_partitions", &partitions, &set);
    if (set && (partitions < 1 || partitions > group.size))
        throw Error("PETSC_OPTIONS: -eps_krylovschur_partitions " + std::to_string(partitions) +
                    " must lie between 1 and the number of MPI ranks, " +
                    std::to_string(group.size));
    group.partitions = int(partitions);
    return group;
}

std::unique_ptr<DistributedEigenproblem> Runtime::distribute(
    const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& massDiagonal,
    const EigenRequest& request) {
    ensurePetsc();
    ensureLogging();
    static const bool defaults = (setFactorizationDefaults(), true);
    (void)defaults;
    Eigen::SparseMatrix<double> k = stiffness;
    k.makeCompressed();
    return std::make_unique<Problem>(k, massDiagonal, request);
}

}  // namespace modeflow

modeflow::PetscRuntime* modeflow_petsc_runtime() {
    static modeflow::Runtime runtime;
    return &runtime;
}
