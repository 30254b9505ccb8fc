#include "engine/reference/ForceProjection.h"

#include <string>

#include "engine/core/MacSampling.h"
#include "engine/core/Error.h"

namespace modeflow::reference {

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

}  // namespace modeflow::reference
