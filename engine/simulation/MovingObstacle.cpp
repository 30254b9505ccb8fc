#include "engine/simulation/MovingObstacle.h"

#include <algorithm>
#include <cmath>

namespace modeflow {

Vec3 MovingObstacle::centreAt(double t) const {
    const auto& path = spec.path;
    if (t <= path.front().first) return path.front().second;
    if (t >= path.back().first) return path.back().second;
    const auto next =
        std::upper_bound(path.begin(), path.end(), t,
                         [](double time, const auto& frame) { return time < frame.first; });
    const auto& [t1, p1] = *next;
    const auto& [t0, p0] = *(next - 1);
    const double s = (t - t0) / (t1 - t0);
    return {p0[0] + s * (p1[0] - p0[0]), p0[1] + s * (p1[1] - p0[1]), p0[2] + s * (p1[2] - p0[2])};
}

Vec3 MovingObstacle::velocityAt(double t) const {
    const auto& path = spec.path;
    if (path.size() < 2 || t < path.front().first || t >= path.back().first) return {0.0, 0.0, 0.0};
    const auto next =
        std::upper_bound(path.begin(), path.end(), t,
                         [](double time, const auto& frame) { return time < frame.first; });
    const auto& [t1, p1] = *next;
    const auto& [t0, p0] = *(next - 1);
    return {(p1[0] - p0[0]) / (t1 - t0), (p1[1] - p0[1]) / (t1 - t0), (p1[2] - p0[2]) / (t1 - t0)};
}

bool MovingObstacle::covers(const Vec3& point, const Vec3& centre, const MacGrid& grid) const {
    const int dim = grid.dim;
    Vec3 d{0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) d[a] = point[a] - centre[a];
    d = grid.minimumImage(d);
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
    }
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= spec.radius * spec.radius;
}

}  // namespace modeflow
