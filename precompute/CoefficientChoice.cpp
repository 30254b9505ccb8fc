#include "precompute/CoefficientChoice.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/core/AvailableMemory.h"
#include "engine/core/PackedLayout.h"
#include "engine/core/SceneKeywords.h"
#include "precompute/coefficients/CoefficientAssembly.h"

namespace modeflow {

TensorChoice chooseTensor(CoefficientStorage requested, int modes, std::int64_t velocityDofs) {
    if (requested != CoefficientStorage::Auto) {
        const bool assemble = requested != CoefficientStorage::TensorFree;
        return {assemble,
                "[basis].coefficients = \"" + std::string(sceneKeyword(requested)) + "\""};
    }
    const double n = modes;
    const double tensorBytes = n * n * (n - 1.0) / 2.0 * 8.0;
    if (const auto available = availableMemory();
        available && tensorBytes > 0.25 * double(*available))
        return {false, "auto: the tensor's " + memoryText(tensorBytes) +
                           " exceed a quarter of the " + memoryText(double(*available)) +
                           " available (a run holds it up to three times)"};
    // Values streamed per evaluation, weighted by their measured cost: N²(N−1)/2 coefficients
    // against 2·V·N basis values.
    const double tensorCost = n * n * (n - 1.0) / 2.0,
                 freeCost = kTensorFreeValueCost * 2.0 * double(velocityDofs) * n;
    std::ostringstream why;
    why.precision(3);
    const bool assemble = tensorCost <= freeCost;
    why << "auto: the " << (assemble ? "tensor" : "tensor-free advection")
        << " streams fewer values per step (" << tensorCost << " coefficients against " << freeCost
        << " weighted basis values for " << modes << " modes on " << velocityDofs << " faces)";
    return {assemble, why.str()};
}

BasisCache::Coefficients storedCoefficients(CoefficientStorage requested,
                                            std::vector<double> packed, int modes) {
    BasisCache::Coefficients c;
    double largest = 0.0;
    for (double x : packed) largest = std::max(largest, std::abs(x));
    const double drop = 1e-12 * largest;
    std::size_t nonZero = 0;
    for (double x : packed) nonZero += std::abs(x) > drop;
    c.density = packed.empty() ? 0.0 : double(nonZero) / double(packed.size());
    // A sparse entry costs 20 bytes against 8, so sparse pays below a density of about 0.25.
    const bool sparse = requested == CoefficientStorage::Sparse ||
                        (requested == CoefficientStorage::Auto && c.density < 0.25);
    if (!sparse) {
        c.storage = BasisCache::Coefficients::Storage::Dense;
        c.packed = std::move(packed);
        return c;
    }
    c.storage = BasisCache::Coefficients::Storage::Sparse;
    const auto n = std::size_t(modes);
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = k + 1; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                const double x = packed[packedIndex(n, k, i, j)];
                if (std::abs(x) <= drop) continue;
                c.k.push_back(std::int32_t(k));
                c.i.push_back(std::int32_t(i));
                c.j.push_back(std::int32_t(j));
                c.value.push_back(x);
            }
    return c;
}

bool completeCoefficients(BasisCache& cache, CoefficientStorage requested, Progress& progress) {
    const bool wanted =
        requested == CoefficientStorage::Dense || requested == CoefficientStorage::Sparse;
    if (!wanted || cache.coefficients.storage != BasisCache::Coefficients::Storage::None)
        return false;
    progress.begin("structural coefficients");
    const int modes = int(cache.velocity.modes.cols());
    cache.coefficients = storedCoefficients(
        requested, assembleStructuralCoefficients(cache.quadrature, cache.velocity.modes), modes);
    cache.timings.emplace_back("coefficients", progress.end());
    return true;
}

}  // namespace modeflow
