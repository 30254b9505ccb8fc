#include "precompute/geometry/FluidMask.h"

#include <algorithm>

#include "precompute/geometry/Domain.h"

namespace modeflow {

std::vector<std::uint8_t> fluidMask(const SceneSpec& scene, const MacGrid& grid) {
    std::vector<std::uint8_t> mask(std::size_t(grid.cellCount()), 1);
    if (scene.domain.empty()) return mask;
    // Mesh level sets at half the finest spacing, as the precompute builds them.
    const double voxel = 0.5 * *std::min_element(grid.spacing.begin(), grid.spacing.begin() + grid.dim);
    const Domain domain(scene.domain, grid.dim, voxel);
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                Vec3 centre{grid.cellCentre(0, x), grid.cellCentre(1, y), 0.0};
                if (grid.dim == 3) centre[2] = grid.cellCentre(2, z);
                mask[std::size_t(grid.cellIndex(x, y, z))] = domain.chi(centre) > 0.0 ? 1 : 0;
            }
    return mask;
}

}  // namespace modeflow
