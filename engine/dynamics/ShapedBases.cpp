#include "engine/dynamics/ShapedBases.h"

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"

namespace modeflow {

std::vector<ShapedBasis> shapedBases(const BasisSpec& basis) {
    std::vector<ShapedBasis> bases;
    std::string label;
    int modes = 0;
    for (const ModeRange& range : basis.velocityModes) {
        if (!label.empty()) label += ',';
        label += std::to_string(range.first);
        label += '-';
        label += std::to_string(range.last);
        modes += range.last - range.first + 1;
        bases.push_back({label, modes});
    }
    return bases;
}

BasisCache leadingModes(const BasisCache& cache, int modes) {
    const auto count = int(cache.velocity.eigenvalues.size());
    if (modes < 1 || modes > count)
        throw Error("shaped basis of " + std::to_string(modes) + " modes: the cache holds " +
                    std::to_string(count));
    BasisCache out = cache;
    // The columns of an eigensolved basis, the descriptors of a closed-form one.
    if (cache.velocity.modes.cols() > 0) out.velocity.modes = cache.velocity.modes.leftCols(modes);
    if (!cache.velocity.separable.empty()) out.velocity.separable.resize(std::size_t(modes));
    out.velocity.eigenvalues = cache.velocity.eigenvalues.head(modes);
    out.velocity.modeNumbers.resize(std::size_t(modes));
    for (std::vector<double>& stokes : out.windStokes)
        if (!stokes.empty()) stokes.resize(std::size_t(modes));
    // The stored coefficients belong to the whole basis; leadingCoefficients gives the rest.
    out.coefficients = {};
    return out;
}

std::unique_ptr<StructuralCoefficients> leadingCoefficients(
    const StructuralCoefficients& coefficients, int modes) {
    if (modes < 1 || modes > coefficients.size())
        throw Error("shaped basis of " + std::to_string(modes) + " modes: the coefficients hold " +
                    std::to_string(coefficients.size()));
    const auto n = std::size_t(modes);
    std::vector<double> packed(packedSize(n));
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = k + 1; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i)
                packed[packedIndex(n, k, i, j)] = coefficients.entry(int(k), int(i), int(j));
    return std::make_unique<DenseCoefficients>(modes, std::move(packed));
}

}  // namespace modeflow
