#include "engine/simulation/MovingObstacle.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "engine/core/Error.h"

namespace modeflow {
namespace {

Eigen::Vector3d vec(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

Vec3 arr(const Eigen::Vector3d& v) {
    return {v[0], v[1], v[2]};
}

double radians(double degrees) {
    return degrees * M_PI / 180.0;
}

/// The index of the key frame ending the segment that holds t (keys by increasing `time`):
/// the first key later than t.
template <typename Keys, typename TimeOf>
std::size_t segmentEnd(const Keys& keys, double t, TimeOf timeOf) {
    return std::size_t(
        std::upper_bound(keys.begin(), keys.end(), t,
                         [&](double time, const auto& key) { return time < timeOf(key); }) -
        keys.begin());
}

double timeOfRotation(const RotationKey& key) {
    return key.time;
}

bool sameAxis(const RotationKey& a, const RotationKey& b) {
    return (vec(a.axis) - vec(b.axis)).norm() <= 1e-12;
}

Eigen::Quaterniond quaternionOf(const RotationKey& key) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(radians(key.degrees), vec(key.axis)));
}

/// From `from` to `to` the shortest way (what Eigen's slerp follows).
Eigen::AngleAxisd turnBetween(const RotationKey& from, const RotationKey& to) {
    Eigen::Quaterniond turn = quaternionOf(from).conjugate() * quaternionOf(to);
    if (turn.w() < 0.0) turn.coeffs() = -turn.coeffs();
    return Eigen::AngleAxisd(turn);
}

double timeOfPosition(const std::pair<double, Vec3>& key) {
    return key.first;
}

/// How far from its frame's origin a level set may cover: its radius, or its farthest corner.
double reachOf(const SolidLevelSet& set) {
    if (set.radius > 0.0) return set.radius;
    double farthest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        Eigen::Vector3d p;
        for (int a = 0; a < 3; ++a)
            p[a] = set.origin[a] + ((corner >> a) & 1) * (set.samples[a] - 1) * set.spacing;
        farthest = std::max(farthest, p.norm());
    }
    return farthest;
}

}  // namespace

Vec3 MovingObstacle::centreAt(double t) const {
    const auto& path = spec.path;
    if (t <= path.front().first) return path.front().second;
    if (t >= path.back().first) return path.back().second;
    const std::size_t end = segmentEnd(path, t, timeOfPosition);
    const auto& [t0, p0] = path[end - 1];
    const auto& [t1, p1] = path[end];
    return arr(vec(p0) + (t - t0) / (t1 - t0) * (vec(p1) - vec(p0)));
}

Vec3 MovingObstacle::velocityAt(double t) const {
    const auto& path = spec.path;
    if (path.size() < 2 || t < path.front().first || t >= path.back().first) return {0.0, 0.0, 0.0};
    const std::size_t end = segmentEnd(path, t, timeOfPosition);
    const auto& [t0, p0] = path[end - 1];
    const auto& [t1, p1] = path[end];
    return arr((vec(p1) - vec(p0)) / (t1 - t0));
}

Eigen::Matrix3d MovingObstacle::orientationAt(double t) const {
    const auto& keys = spec.rotation;
    if (keys.empty()) return Eigen::Matrix3d::Identity();
    if (t <= keys.front().time) return quaternionOf(keys.front()).toRotationMatrix();
    if (t >= keys.back().time) return quaternionOf(keys.back()).toRotationMatrix();
    const std::size_t end = segmentEnd(keys, t, timeOfRotation);
    const RotationKey &k0 = keys[end - 1], &k1 = keys[end];
    const double s = (t - k0.time) / (k1.time - k0.time);
    if (sameAxis(k0, k1))
        return Eigen::AngleAxisd(radians(k0.degrees + s * (k1.degrees - k0.degrees)), vec(k0.axis))
            .toRotationMatrix();
    return quaternionOf(k0).slerp(s, quaternionOf(k1)).toRotationMatrix();
}

Vec3 MovingObstacle::angularVelocityAt(double t) const {
    const auto& keys = spec.rotation;
    if (keys.size() < 2 || t < keys.front().time || t >= keys.back().time) return {0.0, 0.0, 0.0};
    const std::size_t end = segmentEnd(keys, t, timeOfRotation);
    const RotationKey &k0 = keys[end - 1], &k1 = keys[end];
    const double span = k1.time - k0.time;
    if (sameAxis(k0, k1)) return arr(vec(k0.axis) * (radians(k1.degrees - k0.degrees) / span));
    // The slerp turns about a fixed axis of the start's frame, which the turn leaves in place.
    const Eigen::AngleAxisd turn = turnBetween(k0, k1);
    return arr(quaternionOf(k0) * (turn.axis() * (turn.angle() / span)));
}

const SolidLevelSet* MovingObstacle::shapeAt(double t) const {
    if (sequence.empty()) return levelSet.get();
    const double file = std::floor(t * spec.sequenceRate);
    const double last = double(sequence.size() - 1);
    return sequence[std::size_t(std::clamp(std::isfinite(file) ? file : last, 0.0, last))].get();
}

ObstaclePose MovingObstacle::poseAt(double t) const {
    if (drive) return {centreAt(t), orientationAt(t), *drive, {0.0, 0.0, 0.0}, nullptr};
    return {centreAt(t), orientationAt(t), velocityAt(t), angularVelocityAt(t), shapeAt(t)};
}

bool MovingObstacle::covers(const Vec3& point, const ObstaclePose& pose,
                            const MacGrid& grid) const {
    const int dim = grid.dim;
    Vec3 d{0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) d[a] = point[a] - pose.centre[a];
    d = arr(pose.orientation.transpose() * vec(grid.minimumImage(d)));  // into the shape's frame
    switch (spec.shape) {
        case ObstacleShape::Box:
            for (int a = 0; a < dim; ++a)
                if (std::abs(d[a]) > spec.halfSize[a]) return false;
            return true;
        case ObstacleShape::Capsule: {
            // Distance to the segment centre ± axis.
            double along = 0.0, length2 = 0.0;
            for (int a = 0; a < dim; ++a) {
                along += d[a] * spec.axis[a];
                length2 += spec.axis[a] * spec.axis[a];
            }
            const double s = length2 > 0.0 ? std::clamp(along / length2, -1.0, 1.0) : 0.0;
            for (int a = 0; a < dim; ++a) d[a] -= s * spec.axis[a];
            break;
        }
        case ObstacleShape::Ball:
            break;
        case ObstacleShape::Mesh:
            return (pose.shape ? pose.shape : levelSet.get())->depthAt(arr(vec(d) / spec.scale)) >=
                   0.0;
    }
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= spec.radius * spec.radius;
}

double MovingObstacle::reach() const {
    switch (spec.shape) {
        case ObstacleShape::Box:
            return vec(spec.halfSize).norm();
        case ObstacleShape::Capsule:
            return vec(spec.axis).norm() + spec.radius;
        case ObstacleShape::Mesh: {
            double farthest = reachOf(*levelSet);
            for (const auto& file : sequence) farthest = std::max(farthest, reachOf(*file));
            return spec.scale * farthest;
        }
        case ObstacleShape::Ball:
            break;
    }
    return spec.radius;
}

double MovingObstacle::surfaceSpeedBound(double t0, double t1) const {
    if (drive) return 0.0;
    double speed = 0.0, spin = 0.0;
    const auto& path = spec.path;
    for (std::size_t k = 1; k < path.size(); ++k)
        if (path[k].first > t0 && path[k - 1].first < t1)
            speed = std::max(speed, (vec(path[k].second) - vec(path[k - 1].second)).norm() /
                                        (path[k].first - path[k - 1].first));
    const auto& keys = spec.rotation;
    for (std::size_t k = 1; k < keys.size(); ++k)
        if (keys[k].time > t0 && keys[k - 1].time < t1) {
            const double angle = sameAxis(keys[k - 1], keys[k])
                                     ? radians(std::abs(keys[k].degrees - keys[k - 1].degrees))
                                     : turnBetween(keys[k - 1], keys[k]).angle();
            spin = std::max(spin, angle / (keys[k].time - keys[k - 1].time));
        }
    double deforming = 0.0;
    for (const auto& file : sequence) deforming = std::max(deforming, file->maxSpeed);
    return speed + spin * reach() + spec.scale * deforming;
}

Vec3 MovingObstacle::velocityOf(const Vec3& point, const ObstaclePose& pose,
                                const MacGrid& grid) const {
    Vec3 r{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a) r[a] = point[a] - pose.centre[a];
    const Eigen::Vector3d offset = vec(grid.minimumImage(r));
    Eigen::Vector3d velocity = vec(pose.velocity) + vec(pose.angularVelocity).cross(offset);
    if (pose.shape && !pose.shape->velocity.empty()) {
        const Vec3 local = arr(pose.orientation.transpose() * offset / spec.scale);
        velocity += pose.orientation * (spec.scale * vec(pose.shape->velocityAt(local)));
    }
    return arr(velocity);
}

void requireLevelSets(std::span<const MovingObstacle> obstacles) {
    for (std::size_t o = 0; o < obstacles.size(); ++o)
        if (obstacles[o].spec.shape == ObstacleShape::Mesh && !obstacles[o].levelSet)
            throw Error("obstacle #" + std::to_string(o + 1) + " (mesh " +
                        obstacles[o].spec.meshFile.string() +
                        ") has no level set: build it with obstacleSolids before the run");
}

}  // namespace modeflow
