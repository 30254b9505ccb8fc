#include "precompute/closedform/WholeBoxDofs.h"

#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "engine/format/SeparableModes.h"

namespace modeflow {

void fillWholeBoxDofs(BasisCache& cache) {
    const GridSpec& grid = cache.grid;
    const MacGrid mac = MacGrid::fromSpec(grid);
    cache.cellFraction.assign(std::size_t(mac.cellCount()), 1.0);
    cache.cells.resize(std::size_t(mac.cellCount()));
    for (std::int64_t c = 0; c < mac.cellCount(); ++c) cache.cells[std::size_t(c)] = c;
    cache.cellStar = Eigen::VectorXd::Constant(mac.cellCount(), 1.0 / mac.cellVolume());

    cache.faces = wholeBoxFaces(grid);
    Eigen::VectorXd star(Eigen::Index(cache.faces.size()));
    for (std::size_t f = 0; f < cache.faces.size(); ++f) {
        const int a = locateFace(mac, cache.faces[f]).axis;
        star[Eigen::Index(f)] = grid.spacing(a) / mac.faceArea(a);
    }
    cache.faceStar = star;
}

}  // namespace modeflow
