#include "engine/reference/SmokeDisplacement.h"

#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/simulation/SmokeDisplacement.h"

namespace modeflow::reference {
namespace {

/// Calls f(cell index, position) for every cell of `box`, positions wrapped onto the grid.
template <typename F>
void forEachCell(const MacGrid& grid, const CellBox& box, F&& f) {
    for (int z = 0; z < box.count[2]; ++z)
        for (int y = 0; y < box.count[1]; ++y)
            for (int x = 0; x < box.count[0]; ++x) {
                const std::array<int, 3> p{grid.wrap(0, box.first[0] + x),
                                           grid.wrap(1, box.first[1] + y),
                                           grid.wrap(2, box.first[2] + z)};
                f(grid.cellIndex(p[0], p[1], p[2]), p);
            }
}

Vec3 centreOf(const MacGrid& grid, const std::array<int, 3>& p) {
    Vec3 centre{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a) centre[a] = grid.cellCentre(a, p[a]);
    return centre;
}

}  // namespace

SmokeDisplacement::SmokeDisplacement(const MacGrid& smokeGrid,
                                     std::span<const std::uint8_t> fluidMask)
    : mGrid(smokeGrid),
      mFluid(fluidMask.begin(), fluidMask.end()),
      mCoveredAt(std::size_t(smokeGrid.cellCount()), -1),
      mCoverer(mCoveredAt.size(), 0),
      mTarget(mCoveredAt.size(), -1) {
    if (mFluid.size() != mCoveredAt.size())
        throw Error("smoke displacement: a fluid mask of " + std::to_string(mFluid.size()) +
                    " cells for a smoke grid of " + std::to_string(mCoveredAt.size()));
}

std::int64_t SmokeDisplacement::neighbour(const std::array<int, 3>& at,
                                          const std::array<int, 3>& offset) const {
    std::array<int, 3> p{};
    for (int a = 0; a < 3; ++a) {
        p[a] = mGrid.wrap(a, at[a] + offset[a]);
        if (p[a] < 0 || p[a] >= mGrid.cells[a]) return -1;
    }
    return mGrid.cellIndex(p[0], p[1], p[2]);
}

void SmokeDisplacement::step(std::span<const MovingObstacle> solids, double t, double dt,
                             SmokeFields& fields) {
    if (solids.empty()) return;
    if (fields.density.size() != mFluid.size() || fields.temperature.size() != mFluid.size() ||
        (!fields.fuel.empty() && fields.fuel.size() != mFluid.size()))
        throw Error("smoke displacement: fields of " + std::to_string(fields.density.size()) +
                    " cells for a smoke grid of " + std::to_string(mFluid.size()));
    const int substeps = displacementSubsteps(solids, t, dt, mGrid);
    std::vector<ObstaclePose> poses(solids.size());
    for (int k = 1; k <= substeps; ++k) {
        const double time = t + dt * double(k) / double(substeps);
        for (std::size_t o = 0; o < solids.size(); ++o) poses[o] = solids[o].poseAt(time);
        substep(solids, poses, dt, fields);
    }
}

void SmokeDisplacement::substep(std::span<const MovingObstacle> solids,
                                std::span<const ObstaclePose> poses, double dt,
                                SmokeFields& fields) {
    const CellBox box = displacementBox(solids, poses, mGrid);
    std::vector<double> reach;
    for (const MovingObstacle& solid : solids) reach.push_back(solid.reach());
    ++mStamp;
    forEachCell(mGrid, box, [&](std::int64_t cell, const std::array<int, 3>& p) {
        if (!mFluid[std::size_t(cell)]) return;
        const Vec3 centre = centreOf(mGrid, p);
        for (std::size_t o = 0; o < solids.size(); ++o) {
            Vec3 r{0.0, 0.0, 0.0};
            for (int a = 0; a < mGrid.dim; ++a) r[a] = centre[a] - poses[o].centre[a];
            r = mGrid.minimumImage(r);
            if (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] > reach[o] * reach[o]) continue;
            if (solids[o].covers(centre, poses[o], mGrid)) {
                mCoveredAt[std::size_t(cell)] = mStamp;
                mCoverer[std::size_t(cell)] = std::uint8_t(o);
                return;
            }
        }
    });
    const auto offsets = pushOffsets(mGrid.dim);
    forEachCell(mGrid, box, [&](std::int64_t cell, const std::array<int, 3>& p) {
        if (!isCovered(cell)) return;
        const std::size_t o = mCoverer[std::size_t(cell)];
        Vec3 d = pushDirection(solids[o], poses[o], centreOf(mGrid, p), dt, mGrid);
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        int best = -1;
        double bestScore = 0.0;
        for (std::size_t i = 0; i < offsets.size(); ++i) {
            const std::int64_t n = neighbour(p, offsets[i]);
            if (n < 0 || !mFluid[std::size_t(n)] || isCovered(n)) continue;
            const auto& off = offsets[i];
            const double score =
                length > 0.0
                    ? (off[0] * d[0] + off[1] * d[1] + off[2] * d[2]) /
                          (length *
                           std::sqrt(double(off[0] * off[0] + off[1] * off[1] + off[2] * off[2])))
                    : 0.0;
            if (best < 0 || score > bestScore + pushTieMargin) {
                best = int(i);
                bestScore = score;
            }
        }
        mTarget[std::size_t(cell)] = std::int8_t(best);
    });
    // Each free cell gathers what its covered neighbours push to it, in offset order.
    forEachCell(mGrid, box, [&](std::int64_t cell, const std::array<int, 3>& p) {
        if (!mFluid[std::size_t(cell)] || isCovered(cell)) return;
        for (std::size_t i = 0; i < offsets.size(); ++i) {
            const std::array<int, 3> back{-offsets[i][0], -offsets[i][1], -offsets[i][2]};
            const std::int64_t from = neighbour(p, back);
            if (from < 0 || !isCovered(from) || mTarget[std::size_t(from)] != int(i)) continue;
            fields.density[std::size_t(cell)] += fields.density[std::size_t(from)];
            fields.temperature[std::size_t(cell)] += fields.temperature[std::size_t(from)];
            if (!fields.fuel.empty())
                fields.fuel[std::size_t(cell)] += fields.fuel[std::size_t(from)];
        }
    });
    forEachCell(mGrid, box, [&](std::int64_t cell, const std::array<int, 3>&) {
        if (!isCovered(cell)) return;
        fields.density[std::size_t(cell)] = 0.0;
        fields.temperature[std::size_t(cell)] = 0.0;
        if (!fields.fuel.empty()) fields.fuel[std::size_t(cell)] = 0.0;
    });
}

}  // namespace modeflow::reference
