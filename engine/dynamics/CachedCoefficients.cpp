#include "engine/dynamics/CachedCoefficients.h"

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/dynamics/TensorFreeCoefficients.h"

namespace modeflow {
namespace {

using Storage = BasisCache::Coefficients::Storage;

/// The coefficients of `cache`'s velocity modes from `tensor`, its stored tensor (a copy or
/// moved out of it).
std::unique_ptr<StructuralCoefficients> coefficientsOf(const BasisCache& cache,
                                                       BasisCache::Coefficients tensor,
                                                       CoefficientStorage requested) {
    const int n = int(cache.velocity.eigenvalues.size());
    if (requested == CoefficientStorage::TensorFree || tensor.storage == Storage::None) {
        if (requested == CoefficientStorage::Dense || requested == CoefficientStorage::Sparse)
            throw Error(
                "the basis cache holds no structural coefficients (precomputed tensor-free); "
                "precompute the scene again to assemble them");
        if (cache.velocity.source == BasisSource::ClosedForm)
            throw Error(
                "[basis].coefficients = \"tensor-free\": a closed-form basis (a whole box) has "
                "sparse coefficients by selection rules and no vorticity quadrature; use \"auto\"");
        return std::make_unique<TensorFreeCoefficients>(cache.velocity.modes, cache.quadrature);
    }
    if (tensor.storage == Storage::Dense) {
        auto dense = std::make_unique<DenseCoefficients>(n, std::move(tensor.packed));
        if (requested != CoefficientStorage::Sparse) return dense;
        return std::make_unique<SparseCoefficients>(SparseCoefficients::fromDense(*dense));
    }
    if (requested != CoefficientStorage::Dense)
        return std::make_unique<SparseCoefficients>(
            SparseCoefficients::fromLists(n, std::move(tensor.k), std::move(tensor.i),
                                          std::move(tensor.j), std::move(tensor.value)));
    // Refuses entries out of range.
    const SparseCoefficients checked =
        SparseCoefficients::fromLists(n, tensor.k, tensor.i, tensor.j, tensor.value);
    std::vector<double> packed(packedSize(std::size_t(n)), 0.0);
    for (std::size_t e = 0; e < tensor.value.size(); ++e)
        packed[packedIndex(std::size_t(n), std::size_t(tensor.k[e]), std::size_t(tensor.i[e]),
                           std::size_t(tensor.j[e]))] = tensor.value[e];
    return std::make_unique<DenseCoefficients>(n, std::move(packed));
}

}  // namespace

std::unique_ptr<StructuralCoefficients> coefficientsFromCache(const BasisCache& cache,
                                                              CoefficientStorage requested) {
    return coefficientsOf(cache, cache.coefficients, requested);
}

std::unique_ptr<StructuralCoefficients> takeCoefficientsFromCache(BasisCache& cache,
                                                                  CoefficientStorage requested) {
    BasisCache::Coefficients tensor = std::move(cache.coefficients);
    cache.coefficients = BasisCache::Coefficients{};
    cache.coefficients.storage = Storage::None;
    return coefficientsOf(cache, std::move(tensor), requested);
}

}  // namespace modeflow
