#include "engine/simulation/SmokeDisplacement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/NumberText.h"

namespace modeflow {
namespace {

double smallestSpacing(const MacGrid& grid) {
    double h = grid.spacing[0];
    for (int a = 1; a < grid.dim; ++a) h = std::min(h, grid.spacing[a]);
    return h;
}

/// Substeps that keep a surface moving at `speed` within half a cell per substep over dt.
double substepsFor(double speed, double dt, const MacGrid& smokeGrid) {
    return std::max(1.0, std::ceil(speed * dt / (0.5 * smallestSpacing(smokeGrid))));
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
                    numberText(speed * dt / smallestSpacing(smokeGrid)) +
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
                        numberText(speed * dt / smallestSpacing(smokeGrid)) +
                        " smoke cells a step; the smoke follows at most " +
                        std::to_string(maxDisplacementSubsteps / 2) +
                        ": lower dt or slow its key frames");
    }
}

CellBox displacementBox(std::span<const MovingObstacle> solids, std::span<const ObstaclePose> poses,
                        const MacGrid& smokeGrid) {
    CellBox box;
    if (solids.empty()) return box;
    std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};  // inclusive, unwrapped
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::numeric_limits<int>::max();
        hi[a] = std::numeric_limits<int>::min();
    }
    for (std::size_t o = 0; o < solids.size(); ++o) {
        const double reach = solids[o].reach();
        for (int a = 0; a < smokeGrid.dim; ++a) {
            const double h = smokeGrid.spacing[a];
            // Cell centres within reach, and one cell around them.
            const double from = (poses[o].centre[a] - reach - smokeGrid.origin[a]) / h - 0.5;
            const double to = (poses[o].centre[a] + reach - smokeGrid.origin[a]) / h - 0.5;
            const double cells = smokeGrid.cells[a];
            lo[a] =
                std::min(lo[a], int(std::clamp(std::floor(from) - 1.0, -2.0 * cells, 2.0 * cells)));
            hi[a] =
                std::max(hi[a], int(std::clamp(std::ceil(to) + 1.0, -2.0 * cells, 2.0 * cells)));
        }
    }
    for (int a = 0; a < 3; ++a) {
        const int n = smokeGrid.cells[a];
        if (a >= smokeGrid.dim) {
            box.first[a] = 0;
            box.count[a] = n;
        } else if (smokeGrid.periodic[a]) {
            box.first[a] = lo[a];
            box.count[a] = std::min(n, hi[a] - lo[a] + 1);
        } else {
            box.first[a] = std::max(lo[a], 0);
            box.count[a] = std::max(0, std::min(hi[a], n - 1) - box.first[a] + 1);
        }
    }
    return box;
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
