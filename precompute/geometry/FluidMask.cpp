#include "precompute/geometry/FluidMask.h"

#include <algorithm>
#include <optional>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "precompute/geometry/Domain.h"

namespace modeflow {

std::vector<std::uint8_t> fluidMask(const SceneSpec& scene, const BasisCache& cache, int scale) {
    const MacGrid basis = MacGrid::fromSpec(cache.grid);
    const MacGrid grid = basis.refined(scale);
    if (cache.cellFraction.size() != std::size_t(basis.cellCount()))
        throw Error("fluid mask: the basis has " + std::to_string(cache.cellFraction.size()) +
                    " cell fractions for " + std::to_string(basis.cellCount()) + " cells");
    std::vector<std::uint8_t> mask(std::size_t(grid.cellCount()), 0);
    // Mesh level sets at half the finest smoke spacing, as the precompute builds them.
    const bool checkCentres = fluidMaskNeedsDomain(scene, scale);
    std::optional<Domain> domain;
    if (checkCentres)
        domain.emplace(
            scene.domain, grid.dim,
            0.5 * *std::min_element(grid.spacing.begin(), grid.spacing.begin() + grid.dim));
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                if (cache.cellFraction[std::size_t(
                        basis.cellIndex(x / scale, y / scale, z / scale))] <= 0.0)
                    continue;
                Vec3 centre{grid.cellCentre(0, x), grid.cellCentre(1, y), 0.0};
                if (grid.dim == 3) centre[2] = grid.cellCentre(2, z);
                if (!checkCentres || domain->chi(centre) > 0.0)
                    mask[std::size_t(grid.cellIndex(x, y, z))] = 1;
            }
    return mask;
}

bool fluidMaskNeedsDomain(const SceneSpec& scene, int scale) {
    return scale > 1 && !scene.domain.empty();
}

}  // namespace modeflow
