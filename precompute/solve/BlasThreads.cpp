#include "precompute/solve/BlasThreads.h"

#include <dlfcn.h>

namespace modeflow {
namespace {

struct OpenBlasThreads {
    using Set = void (*)(int);
    using Get = int (*)();
    Set set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    Get get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    bool found() const { return set && get; }
};

const OpenBlasThreads& openBlas() {
    static const OpenBlasThreads functions;
    return functions;
}

}  // namespace

bool BlasThreads::controllable() {
    return openBlas().found();
}

BlasThreads::BlasThreads(int threads) {
    if (!controllable()) return;
    mSaved = openBlas().get();
    openBlas().set(threads);
}

BlasThreads::~BlasThreads() {
    if (mSaved > 0) openBlas().set(mSaved);
}

}  // namespace modeflow
