#include "precompute/solve/ProcessGroup.h"

#include <cstdlib>
#include <string>

#include <slepcsys.h>

#include "engine/core/Error.h"
#include "engine/core/LaunchedRank.h"
#include "engine/core/LibraryLeaks.h"

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

}  // namespace

void ensurePetsc() {
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

std::string lastPetscErrorMessage() {
    return petscMessage();
}

ProcessGroup joinProcessGroup() {
    if (launchedRank().launched) ensurePetsc();
    return currentProcessGroup();
}

ProcessGroup currentProcessGroup() {
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

}  // namespace modeflow
