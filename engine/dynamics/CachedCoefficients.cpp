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

}  // namespace

std::unique_ptr<StructuralCoefficients> coefficientsFromCache(const BasisCache& cache,
                                                              CoefficientStorage requested) {
    const auto& c = cache.coefficients;
    const int n = int(cache.velocity.eigenvalues.size());
    if (requested == CoefficientStorage::TensorFree || c.storage == Storage::None) {
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
    if (c.storage == Storage::Dense) {
        auto dense = std::make_unique<DenseCoefficients>(n, c.packed);
        if (requested != CoefficientStorage::Sparse) return dense;
        return std::make_unique<SparseCoefficients>(SparseCoefficients::fromDense(*dense));
    }
    SparseCoefficients sparse(n, entriesOf(c));
    if (requested != CoefficientStorage::Dense)
        return std::make_unique<SparseCoefficients>(std::move(sparse));
    std::vector<double> packed(packedSize(std::size_t(n)), 0.0);
    for (std::size_t e = 0; e < c.value.size(); ++e)
        packed[packedIndex(std::size_t(n), std::size_t(c.k[e]), std::size_t(c.i[e]),
                           std::size_t(c.j[e]))] = c.value[e];
    return std::make_unique<DenseCoefficients>(n, std::move(packed));
}

}  // namespace modeflow
