#include "engine/dynamics/CachedCoefficients.h"

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"

namespace modeflow {

std::unique_ptr<StructuralCoefficients> coefficientsFromCache(const BasisCache& cache) {
    const auto& c = cache.coefficients;
    const int n = int(cache.velocity.eigenvalues.size());
    if (c.storage == BasisCache::Coefficients::Storage::Dense)
        return std::make_unique<DenseCoefficients>(n, c.packed);
    std::vector<CoefficientEntry> entries(c.value.size());
    for (std::size_t e = 0; e < entries.size(); ++e)
        entries[e] = {c.k[e], c.i[e], c.j[e], c.value[e]};
    return std::make_unique<SparseCoefficients>(n, std::move(entries));
}

}  // namespace modeflow
