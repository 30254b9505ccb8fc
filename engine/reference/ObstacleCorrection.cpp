#include "engine/reference/ObstacleCorrection.h"

#include "engine/core/FaceLocation.h"
#include "engine/core/MacSampling.h"
#include "engine/reference/ForceProjection.h"

namespace modeflow::reference {

std::vector<double> obstacleMismatch(const BasisCache& cache, std::span<const double> faceField,
                                     std::span<const MovingObstacle> obstacles, double t) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    requireFaceField(grid, faceField.size(), "obstacle mismatch");
    requireLevelSets(obstacles);
    std::vector<ObstaclePose> poses;
    for (const MovingObstacle& o : obstacles) poses.push_back(o.poseAt(t));
    std::vector<double> mismatch(faceField.size(), 0.0);
    for (const std::int64_t face : cache.faces) {
        const FaceLocation location = locateFace(grid, face);
        const Vec3 centre = faceCentre(grid, location);
        for (std::size_t o = 0; o < obstacles.size(); ++o)
            if (obstacles[o].covers(centre, poses[o], grid)) {
                mismatch[std::size_t(face)] =
                    faceField[std::size_t(face)] -
                    obstacles[o].velocityOf(centre, poses[o], grid)[location.axis];
                break;  // the first obstacle covering a face sets its velocity
            }
    }
    return mismatch;
}

Eigen::VectorXd obstacleCorrection(const VelocityBasis& basis, std::span<const double> faceField,
                                   std::span<const MovingObstacle> obstacles, double t) {
    return projectFaceField(basis, obstacleMismatch(basis.cache(), faceField, obstacles, t));
}

Eigen::VectorXd obstacleCorrection(const BasisCache& cache, std::span<const double> faceField,
                                   std::span<const MovingObstacle> obstacles, double t) {
    return obstacleCorrection(VelocityBasis(cache), faceField, obstacles, t);
}

}  // namespace modeflow::reference
