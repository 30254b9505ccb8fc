#include "precompute/solve/HugePages.h"

#include <sys/mman.h>

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>

#include <SuiteSparse_config.h>

namespace modeflow {
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;

void* suiteSparseMalloc(std::size_t bytes) {
    if (bytes < kHugePage) return std::malloc(bytes);
    try {
        return allocateHugePages(bytes);
    } catch (const std::bad_alloc&) {
        return nullptr;  // CHOLMOD reports it as out of memory
    }
}

void* suiteSparseCalloc(std::size_t count, std::size_t size) {
    if (size != 0 && count > std::size_t(-1) / size) return nullptr;
    const std::size_t bytes = count * size;
    if (bytes < kHugePage) return std::calloc(count, size);
    void* p = suiteSparseMalloc(bytes);
    if (p) std::memset(p, 0, bytes);
    return p;
}

}  // namespace

void* allocateHugePages(std::size_t bytes) {
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded == 0 ? kHugePage : rounded);
    if (!p) throw std::bad_alloc();
    // Only advice: where the kernel has no huge pages to give, the memory stays in small ones.
    madvise(p, rounded, MADV_HUGEPAGE);
    return p;
}

void HugePageMatrix::Free::operator()(double* p) const {
    std::free(p);
}

HugePageMatrix::HugePageMatrix(Eigen::Index rows, Eigen::Index cols)
    : mData(static_cast<double*>(
          allocateHugePages(std::size_t(rows) * std::size_t(cols) * sizeof(double)))),
      mMap(mData.get(), rows, cols) {}

void useHugePagesForSuiteSparse() {
    static std::once_flag once;
    std::call_once(once, [] {
        SuiteSparse_config.malloc_func = suiteSparseMalloc;
        SuiteSparse_config.calloc_func = suiteSparseCalloc;
    });
}

}  // namespace modeflow
