#include "engine/dynamics/CachedCoefficients.h"

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/dynamics/TensorFreeCoefficients.h"

namespace modeflow {
namespace {

using Storage = BasisCache::Coefficients::Storage;

std::vector<CoefficientEntry> entriesOf(const BasisCache::Coefficients& c) {
    std::vector<CoefficientEntry> entries(c.value.size());
    for (std::size_t e = 0; e < entries.size(); ++e)
        entries[e] = {c.k[e], c.i[e], c.j[e], c.value[e]};
    return entries;
}

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
    std::vector<CoefficientEntry> entries = entriesOf(tensor);
    if (requested != CoefficientStorage::Dense) {
        tensor = {};  // copied into entries: freed before they are sorted
        return std::make_unique<SparseCoefficients>(n, std::move(entries));
    }
    const SparseCoefficients checked(n, std::move(entries));  // refuses entries out of range
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
