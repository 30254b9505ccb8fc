#include "engine/reference/ForceProjection.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"

namespace modeflow::reference {

Eigen::VectorXd projectForce(const VelocityBasis& basis, const Eigen::VectorXd& q,
                             FaceQuantity quantity) {
    if (q.size() != basis.dofCount())
        throw Error("force projection: " + std::to_string(q.size()) +
                    " face values for a basis on " + std::to_string(basis.dofCount()) + " faces");
    return basis.transposed(projectionWeights(basis.cache(), quantity).cwiseProduct(q));
}

Eigen::VectorXd projectForce(const BasisCache& cache, const Eigen::VectorXd& q,
                             FaceQuantity quantity) {
    return projectForce(VelocityBasis(cache), q, quantity);
}

Eigen::VectorXd projectFaceField(const VelocityBasis& basis, std::span<const double> faceField) {
    const BasisCache& cache = basis.cache();
    requireFaceField(MacGrid::fromSpec(cache.grid), faceField.size(), "force projection");
    Eigen::VectorXd q(Eigen::Index(cache.faces.size()));
    for (std::size_t d = 0; d < cache.faces.size(); ++d)
        q[Eigen::Index(d)] = faceField[std::size_t(cache.faces[d])];
    return projectForce(basis, q, FaceQuantity::FaceField);
}

Eigen::VectorXd projectFaceField(const BasisCache& cache, std::span<const double> faceField) {
    return projectFaceField(VelocityBasis(cache), faceField);
}

}  // namespace modeflow::reference
