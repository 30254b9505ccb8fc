#include "precompute/solve/ProcessGroup.h"

#include "engine/core/LaunchedRank.h"
#include "precompute/solve/PetscRuntime.h"

namespace modeflow {

void ensurePetsc() {
    petscRuntime().start();
}

std::string lastPetscErrorMessage() {
    return petscRuntimeLoaded() ? petscRuntime().lastError() : std::string();
}

ProcessGroup joinProcessGroup() {
    if (launchedRank().launched) ensurePetsc();
    return currentProcessGroup();
}

ProcessGroup currentProcessGroup() {
    if (!petscRuntimeLoaded() || !petscRuntime().started()) return {};
    return petscRuntime().group();
}

}  // namespace modeflow
