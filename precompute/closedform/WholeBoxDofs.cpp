#include "precompute/closedform/WholeBoxDofs.h"

#include "engine/core/MacGrid.h"

namespace modeflow {

void fillWholeBoxDofs(BasisCache& cache) {
    const GridSpec& grid = cache.grid;
    const MacGrid mac = MacGrid::fromSpec(grid);
    cache.cellFraction.assign(std::size_t(mac.cellCount()), 1.0);
    cache.cells.resize(std::size_t(mac.cellCount()));
    for (std::int64_t c = 0; c < mac.cellCount(); ++c) cache.cells[std::size_t(c)] = c;
    cache.cellStar = Eigen::VectorXd::Constant(mac.cellCount(), 1.0 / mac.cellVolume());

    cache.faces.clear();
    std::vector<double> star;
    for (int a = 0; a < grid.dim; ++a) {
        const std::array<int, 3> e = mac.faceExtent(a);
        const int first = grid.isPeriodic(a) ? 0 : 1;
        const int last = grid.resolution[a] - 1;  // a wall at n_a; on a periodic axis, face 0 again
        for (int z = 0; z < e[2]; ++z)
            for (int y = 0; y < e[1]; ++y)
                for (int x = 0; x < e[0]; ++x) {
                    const std::array<int, 3> p{x, y, z};
                    if (p[a] < first || p[a] > last) continue;
                    cache.faces.push_back(mac.faceIndex(a, x, y, z));
                    star.push_back(grid.spacing(a) / mac.faceArea(a));
                }
    }
    cache.faceStar = Eigen::Map<Eigen::VectorXd>(star.data(), Eigen::Index(star.size()));
}

}  // namespace modeflow
