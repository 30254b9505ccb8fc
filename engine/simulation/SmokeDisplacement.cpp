#include "engine/simulation/SmokeDisplacement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/NumberText.h"

namespace modeflow {
namespace {

/// Substeps that keep a surface moving at `speed` within half a cell per substep over dt.
double substepsFor(double speed, double dt, const MacGrid& smokeGrid) {
    return std::max(1.0, std::ceil(speed * dt / (0.5 * smokeGrid.smallestSpacing())));
}

/// The least and greatest offsets from its centre, per world axis, of the points `solid` may
/// cover at `pose`: its shape's box in its own frame (a mesh's lattice), turned, within its reach.
std::pair<Vec3, Vec3> coveredOffsets(const MovingObstacle& solid, const ObstaclePose& pose) {
    const ObstacleSpec& spec = solid.spec;
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  // own frame
    switch (spec.shape) {
        case ObstacleShape::Box:
            hi = Eigen::Vector3d(spec.halfSize[0], spec.halfSize[1], spec.halfSize[2]);
            lo = -hi;
            break;
        case ObstacleShape::Capsule:
            for (int a = 0; a < 3; ++a) hi[a] = std::abs(spec.axis[a]) + spec.radius;
            lo = -hi;
            break;
        case ObstacleShape::Mesh: {
            const SolidLevelSet& set = pose.shape ? *pose.shape : *solid.levelSet;
            for (int a = 0; a < 3; ++a) {
                lo[a] = spec.scale * set.origin[a];
                hi[a] = spec.scale * (set.origin[a] + (set.samples[a] - 1) * set.spacing);
            }
            break;
        }
        case ObstacleShape::Ball:
            hi = Eigen::Vector3d::Constant(spec.radius);
            lo = -hi;
            break;
    }
    const double reach = solid.reach();
    Vec3 near{-reach, -reach, -reach}, far{reach, reach, reach};
    Eigen::Vector3d least = Eigen::Vector3d::Constant(reach), most = -least;
    for (int corner = 0; corner < 8; ++corner) {
        Eigen::Vector3d p;
        for (int a = 0; a < 3; ++a) p[a] = (corner >> a) & 1 ? hi[a] : lo[a];
        const Eigen::Vector3d turned = pose.orientation * p;
        least = least.cwiseMin(turned);
        most = most.cwiseMax(turned);
    }
    for (int a = 0; a < 3; ++a) {
        near[a] = std::max(near[a], least[a]);
        far[a] = std::min(far[a], most[a]);
    }
    return {near, far};
}

std::vector<std::array<int, 3>> offsetsOf(int dim) {
    std::vector<std::array<int, 3>> offsets;
    const int zs = dim == 3 ? 1 : 0;
    for (int z = -zs; z <= zs; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                if (x != 0 || y != 0 || z != 0) offsets.push_back({x, y, z});
    return offsets;
}

}  // namespace

int displacementSubsteps(std::span<const MovingObstacle> solids, double t, double dt,
                         const MacGrid& smokeGrid) {
    double speed = 0.0;
    for (const MovingObstacle& solid : solids)
        speed = std::max(speed, solid.surfaceSpeedBound(t, t + dt));
    const double substeps = substepsFor(speed, dt, smokeGrid);
    if (substeps > maxDisplacementSubsteps)
        throw Error("a solid's surface moves " +
                    numberText(speed * dt / smokeGrid.smallestSpacing()) +
                    " smoke cells in the step at t = " + numberText(t) + "; at most " +
                    std::to_string(maxDisplacementSubsteps / 2) + ": lower dt or slow it down");
    return int(substeps);
}

void requireDisplaceableMotion(std::span<const MovingObstacle> solids, double dt,
                               const MacGrid& smokeGrid) {
    constexpr double always = std::numeric_limits<double>::infinity();
    for (std::size_t o = 0; o < solids.size(); ++o) {
        const double speed = solids[o].surfaceSpeedBound(-always, always);
        if (substepsFor(speed, dt, smokeGrid) > maxDisplacementSubsteps)
            throw Error("obstacle #" + std::to_string(o + 1) + "'s surface moves up to " +
                        numberText(speed * dt / smokeGrid.smallestSpacing()) +
                        " smoke cells a step; the smoke follows at most " +
                        std::to_string(maxDisplacementSubsteps / 2) +
                        ": lower dt or slow its key frames");
    }
}

CellBox displacementBox(std::span<const MovingObstacle> solids, std::span<const ObstaclePose> poses,
                        const MacGrid& grid) {
    CellBox box;
    if (solids.empty()) return box;
    std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};  // inclusive, unwrapped
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::numeric_limits<int>::max();
        hi[a] = std::numeric_limits<int>::min();
    }
    for (std::size_t o = 0; o < solids.size(); ++o) {
        const auto [near, far] = coveredOffsets(solids[o], poses[o]);
        for (int a = 0; a < grid.dim; ++a) {
            const double h = grid.spacing[a];
            // Its centre in the grid along a periodic axis (a path may go round it many times).
            double centre = poses[o].centre[a] - grid.origin[a];
            if (grid.periodic[a]) centre -= grid.length(a) * std::floor(centre / grid.length(a));
            // The cell centres it may cover, and one cell around them.
            const double from = (centre + near[a]) / h - 0.5;
            const double to = (centre + far[a]) / h - 0.5;
            const double cells = grid.cells[a];
            lo[a] =
                std::min(lo[a], int(std::clamp(std::floor(from) - 1.0, -2.0 * cells, 2.0 * cells)));
            hi[a] =
                std::max(hi[a], int(std::clamp(std::ceil(to) + 1.0, -2.0 * cells, 2.0 * cells)));
        }
    }
    for (int a = 0; a < 3; ++a) {
        const int n = grid.cells[a];
        if (a >= grid.dim) {
            box.first[a] = 0;
            box.count[a] = n;
        } else if (grid.periodic[a]) {
            box.first[a] = lo[a];
            box.count[a] = std::min(n, hi[a] - lo[a] + 1);
        } else {
            box.first[a] = std::max(lo[a], 0);
            box.count[a] = std::max(0, std::min(hi[a], n - 1) - box.first[a] + 1);
        }
    }
    return box;
}

bool boxContains(const CellBox& outer, const CellBox& inner, const MacGrid& grid) {
    if (inner.cellCount() == 0) return true;
    for (int a = 0; a < 3; ++a) {
        const int n = grid.cells[a];
        if (a < grid.dim && grid.periodic[a]) {
            if (outer.count[a] >= n) continue;
            const int offset = ((inner.first[a] - outer.first[a]) % n + n) % n;
            if (offset + inner.count[a] > outer.count[a]) return false;
        } else if (inner.first[a] < outer.first[a] ||
                   inner.first[a] + inner.count[a] > outer.first[a] + outer.count[a]) {
            return false;
        }
    }
    return true;
}

CellBox sweptDisplacementBox(std::span<const MovingObstacle> solids, double t, double dt, int steps,
                             const MacGrid& grid) {
    // Each solid once per step: the box's extremes over all of them.
    std::vector<MovingObstacle> each;
    std::vector<ObstaclePose> poses;
    for (int s = 0; s < steps; ++s)
        for (const MovingObstacle& solid : solids) {
            each.push_back(solid);
            poses.push_back(solid.poseAt(t + dt * double(s)));
        }
    return displacementBox(each, poses, grid);
}

std::vector<CellBox> displacementBoxes(std::span<const MovingObstacle> solids,
                                       std::span<const ObstaclePose> poses,
                                       const MacGrid& smokeGrid) {
    const CellBox all = displacementBox(solids, poses, smokeGrid);
    std::vector<CellBox> each;
    std::int64_t cells = 0;
    for (std::size_t o = 0; o < solids.size(); ++o) {
        each.push_back(displacementBox(solids.subspan(o, 1), poses.subspan(o, 1), smokeGrid));
        cells += each.back().cellCount();
    }
    if (cells < all.cellCount()) return each;
    return {all};
}

std::span<const std::array<int, 3>> pushOffsets(int dim) {
    static const std::vector<std::array<int, 3>> planar = offsetsOf(2), solid = offsetsOf(3);
    return dim == 3 ? solid : planar;
}

Vec3 pushDirection(const MovingObstacle& solid, const ObstaclePose& pose, const Vec3& point,
                   double dt, const MacGrid& smokeGrid) {
    const Vec3 velocity = solid.velocityOf(point, pose, smokeGrid);
    Vec3 cells{0.0, 0.0, 0.0};
    double moved = 0.0;
    for (int a = 0; a < smokeGrid.dim; ++a) {
        cells[a] = velocity[a] / smokeGrid.spacing[a];
        moved += cells[a] * cells[a];
    }
    if (std::sqrt(moved) * dt >= 1e-3) return cells;
    Vec3 r{0.0, 0.0, 0.0};
    for (int a = 0; a < smokeGrid.dim; ++a) r[a] = point[a] - pose.centre[a];
    r = smokeGrid.minimumImage(r);
    for (int a = 0; a < smokeGrid.dim; ++a) cells[a] = r[a] / smokeGrid.spacing[a];
    return cells;
}

}  // namespace modeflow
