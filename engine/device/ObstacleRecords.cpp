#include "engine/device/ObstacleRecords.h"

namespace modeflow::device {
namespace {

void copy3(float to[3], const Vec3& from) {
    for (int a = 0; a < 3; ++a) to[a] = float(from[a]);
}

/// The shape's OBSTACLE_* code.
std::uint32_t shapeCode(ObstacleShape shape) {
    return shape == ObstacleShape::Box       ? OBSTACLE_BOX
           : shape == ObstacleShape::Capsule ? OBSTACLE_CAPSULE
           : shape == ObstacleShape::Mesh    ? OBSTACLE_MESH
                                             : OBSTACLE_BALL;
}

}  // namespace

std::uint32_t solidKinds(std::span<const MovingObstacle> solids) {
    std::uint32_t kinds = 0;
    for (const MovingObstacle& solid : solids) {
        kinds |= 1u << shapeCode(solid.spec.shape);
        if (!solid.sequence.empty()) kinds |= SOLID_KIND_DEFORMING;
    }
    return kinds;
}

shaders::ObstacleRecord obstacleRecord(const MovingObstacle& obstacle, const ObstaclePose& pose,
                                       const ObstacleLattices& lattices) {
    const ObstacleSpec& spec = obstacle.spec;
    shaders::ObstacleRecord r{};
    copy3(r.centre, pose.centre);
    copy3(r.velocity, pose.velocity);
    copy3(r.spin, pose.angularVelocity);
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row)
            r.orientation[4 * column + row] = float(pose.orientation(row, column));
    copy3(r.halfSize, spec.halfSize);
    copy3(r.axis, spec.axis);
    r.radius = float(spec.radius);
    r.scale = float(spec.scale);
    // Rounded up a little: float's rounding must not cut off a covered point.
    r.reach = float(1.0001 * obstacle.reach() + 1e-6);
    r.shape = shapeCode(spec.shape);
    r.velocityStart = LatticePlace::kNoVelocity;
    if (const SolidLevelSet* lattice = pose.shape ? pose.shape : obstacle.levelSet.get()) {
        copy3(r.latticeOrigin, lattice->origin);
        r.latticeSpacing = float(lattice->spacing);
        for (int a = 0; a < 3; ++a) r.latticeSamples[a] = std::uint32_t(lattice->samples[a]);
        const LatticePlace place = lattices.placeOf(lattice);
        r.latticeStart = place.depth;
        r.velocityStart = place.velocity;
    }
    return r;
}

}  // namespace modeflow::device
