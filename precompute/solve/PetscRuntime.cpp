#include "precompute/solve/PetscRuntime.h"

#include <dlfcn.h>

#include <atomic>
#include <mutex>
#include <string>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

std::atomic<PetscRuntime*> gLoaded{nullptr};

PetscRuntime* load() {
    // RTLD_GLOBAL: Open MPI's own components, which it loads as it starts, look for its symbols
    // in the global scope.
    const char* path = MODEFLOW_PETSC_MODULE;
    void* module = dlopen(path, RTLD_NOW | RTLD_GLOBAL);
    if (module == nullptr)
        throw Error(std::string("the sliced eigensolver's module ") + path + " cannot be loaded (" +
                    dlerror() + "); build modeflow again (tools/build.sh)");
    using Entry = PetscRuntime* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(module, "modeflow_petsc_runtime"));
    if (entry == nullptr)
        throw Error(std::string("the sliced eigensolver's module ") + path +
                    " has no entry point modeflow_petsc_runtime");
    return entry();
}

}  // namespace

PetscRuntime& petscRuntime() {
    static std::mutex loading;
    const std::lock_guard lock(loading);
    if (gLoaded.load() == nullptr) gLoaded.store(load());
    return *gLoaded.load();
}

bool petscRuntimeLoaded() {
    return gLoaded.load() != nullptr;
}

}  // namespace modeflow
