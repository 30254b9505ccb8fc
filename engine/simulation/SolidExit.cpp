#include "engine/simulation/SolidExit.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace modeflow {
namespace {

using Eigen::Vector3d;

Vector3d vec(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

Vec3 arr(const Vector3d& v) {
    return {v[0], v[1], v[2]};
}

/// A unit vector across `axis` (in the plane in 2D): for a point on a capsule's segment.
Vector3d across(const Vector3d& axis, int dim) {
    if (dim == 2) return Vector3d(-axis.y(), axis.x(), 0.0).normalized();
    const Vector3d helper =
        std::abs(axis.x()) <= std::abs(axis.y()) ? Vector3d::UnitX() : Vector3d::UnitY();
    return axis.cross(helper).normalized();
}

/// The exit of `d` (shape frame, covered) from an analytic shape: its new place and normal.
std::pair<Vector3d, Vector3d> analyticExit(const ObstacleSpec& spec, Vector3d d, int dim,
                                           double margin) {
    if (spec.shape == ObstacleShape::Box) {
        int nearest = 0;
        for (int a = 1; a < dim; ++a)
            if (spec.halfSize[a] - std::abs(d[a]) < spec.halfSize[nearest] - std::abs(d[nearest]))
                nearest = a;
        const double side = d[nearest] >= 0.0 ? 1.0 : -1.0;
        d[nearest] = side * (spec.halfSize[nearest] + margin);
        return {d, side * Vector3d::Unit(nearest)};
    }
    Vector3d base = Vector3d::Zero();
    if (spec.shape == ObstacleShape::Capsule) {
        const Vector3d axis = vec(spec.axis);
        const double length2 = axis.squaredNorm();
        base = (length2 > 0.0 ? std::clamp(d.dot(axis) / length2, -1.0, 1.0) : 0.0) * axis;
    }
    const Vector3d q = d - base;
    const double length = q.norm();
    Vector3d normal = Vector3d::UnitX();
    if (length > 0.0)
        normal = q / length;
    else if (spec.shape == ObstacleShape::Capsule && vec(spec.axis).squaredNorm() > 0.0)
        normal = across(vec(spec.axis), dim);
    return {base + normal * (spec.radius + margin), normal};
}

/// The exit of `p` (mesh units, covered) along the level set's gradient.
std::pair<Vector3d, Vector3d> meshExit(const SolidLevelSet& set, Vector3d p, double margin) {
    Vector3d normal = Vector3d::UnitZ();
    for (int step = 0; step < kMeshExitSteps; ++step) {
        // The gradient from the depth's own samples: one lattice cell's eight a step (the device
        // reads each sample as a texel fetch).
        Vec3 slope;
        const double depth = set.depthAt(arr(p), slope);
        if (depth < 0.0) break;
        const Vector3d gradient = vec(slope);
        // Depth grows inwards: out is down its gradient.
        if (gradient.norm() > 0.0) normal = -gradient.normalized();
        p += normal * (depth + margin);
    }
    return {p, normal};
}

}  // namespace

std::optional<SolidExit> solidExit(const MovingObstacle& solid, const Vec3& point,
                                   const ObstaclePose& pose, const MacGrid& grid, double margin) {
    if (!solid.covers(point, pose, grid)) return std::nullopt;
    Vec3 offset{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a) offset[a] = point[a] - pose.centre[a];
    const Vector3d d = pose.orientation.transpose() * vec(grid.minimumImage(offset));
    Vector3d place, normal;
    if (solid.spec.shape == ObstacleShape::Mesh) {
        const SolidLevelSet& set = pose.shape ? *pose.shape : *solid.levelSet;
        const double scale = solid.spec.scale;
        std::tie(place, normal) = meshExit(set, d / scale, margin / scale);
        place *= scale;
    } else {
        std::tie(place, normal) = analyticExit(solid.spec, d, grid.dim, margin);
    }
    const Vector3d moved = pose.orientation * (place - d);
    Vec3 exit = point;
    for (int a = 0; a < grid.dim; ++a) exit[a] += moved[a];
    return SolidExit{exit, arr(pose.orientation * normal)};
}

}  // namespace modeflow
