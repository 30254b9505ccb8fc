#include "engine/field/ForceProjection.h"

#include <string>

#include "engine/field/FaceLocation.h"
#include "engine/field/MacSampling.h"
#include "engine/format/Error.h"

namespace modeflow {

Eigen::VectorXd projectionWeights(const BasisCache& cache, FaceQuantity quantity) {
    if (cache.faceStar.size() != Eigen::Index(cache.faces.size()))
        throw Error("force projection: " + std::to_string(cache.faceStar.size()) + " Hodge stars for " +
                    std::to_string(cache.faces.size()) + " face DOFs");
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    Eigen::VectorXd w(Eigen::Index(cache.faces.size()));
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const int axis = locateFace(grid, cache.faces[d]).axis;
        const auto i = Eigen::Index(d);
        w[i] = quantity == FaceQuantity::Density ? grid.spacing[axis] : grid.faceArea(axis) * cache.faceStar[i];
    }
    return w;
}

Eigen::VectorXd projectForce(const BasisCache& cache, const Eigen::VectorXd& q, FaceQuantity quantity) {
    if (q.size() != cache.velocity.modes.rows())
        throw Error("force projection: " + std::to_string(q.size()) + " face values for a basis on " +
                    std::to_string(cache.velocity.modes.rows()) + " faces");
    return cache.velocity.modes.transpose() * projectionWeights(cache, quantity).cwiseProduct(q);
}

Eigen::VectorXd projectFaceField(const BasisCache& cache, std::span<const double> faceField) {
    requireFaceField(MacGrid::fromSpec(cache.grid), faceField.size(), "force projection");
    Eigen::VectorXd q(Eigen::Index(cache.faces.size()));
    for (std::size_t d = 0; d < cache.faces.size(); ++d) q[Eigen::Index(d)] = faceField[std::size_t(cache.faces[d])];
    return projectForce(cache, q, FaceQuantity::FaceField);
}

}  // namespace modeflow
