#include "engine/simulation/ProjectionWeights.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"

namespace modeflow {

Eigen::VectorXd projectionWeights(const BasisCache& cache, FaceQuantity quantity) {
    if (cache.faceStar.size() != Eigen::Index(cache.faces.size()))
        throw Error("force projection: " + std::to_string(cache.faceStar.size()) +
                    " Hodge stars for " + std::to_string(cache.faces.size()) + " face DOFs");
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    Eigen::VectorXd w(Eigen::Index(cache.faces.size()));
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const int axis = locateFace(grid, cache.faces[d]).axis;
        const auto i = Eigen::Index(d);
        w[i] = quantity == FaceQuantity::Density ? grid.spacing[axis]
                                                 : grid.faceArea(axis) * cache.faceStar[i];
    }
    return w;
}

}  // namespace modeflow
