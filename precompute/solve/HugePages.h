#pragma once
/// @file HugePages.h
/// Large arrays of the eigensolves in 2 MB pages where the kernel offers them (madvise), for
/// the arrays that every product streams through: the search space, the factorization.
/// In a virtual machine each 4 KB page's TLB miss walks two page tables and each first touch is
/// a trap to the hypervisor; measured on the seed's sphere scene (32²×48, 230 modes, two cores),
/// the block eigensolve's solves took 86 s in 4 KB pages and 23 s in 2 MB ones.

#include <cstddef>
#include <memory>

#include <Eigen/Core>

namespace modeflow {

/// `bytes` of memory aligned to 2 MB and advised to the kernel as huge pages; std::free frees it.
/// @throw std::bad_alloc when there is none.
void* allocateHugePages(std::size_t bytes);

/// A dense column-major matrix of doubles in huge pages, used through `map()`.
class HugePageMatrix {
public:
    HugePageMatrix(Eigen::Index rows, Eigen::Index cols);
    Eigen::Map<Eigen::MatrixXd>& map() { return mMap; }
    const Eigen::Map<Eigen::MatrixXd>& map() const { return mMap; }

private:
    struct Free {
        void operator()(double* p) const;
    };
    std::unique_ptr<double, Free> mData;
    Eigen::Map<Eigen::MatrixXd> mMap;
};

/// Routes SuiteSparse's (CHOLMOD's) allocations of 2 MB and more to allocateHugePages, for the
/// rest of the process; smaller ones stay with malloc.
void useHugePagesForSuiteSparse();

}  // namespace modeflow
