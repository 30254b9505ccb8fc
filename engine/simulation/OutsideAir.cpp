#include "engine/simulation/OutsideAir.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/SceneKeywords.h"

namespace modeflow {
namespace {

/// The two axes along a side across `axis`, in increasing order.
std::array<int, 2> alongSide(int axis) {
    return {axis == 0 ? 1 : 0, axis == 2 ? 1 : 2};
}

}  // namespace

OutsideAir::OutsideAir(const MacGrid& smokeGrid, std::array<bool, 6> sides,
                       std::array<double, 3> base)
    : mGrid(smokeGrid), mSides(sides), mBase(base) {
    for (int side = 0; side < 6; ++side) {
        const auto [b, c] = alongSide(side / 2);
        const std::int64_t count =
            side < 2 * mGrid.dim ? std::int64_t(mGrid.cells[b]) * mGrid.cells[c] : 0;
        mOffset[std::size_t(side + 1)] = mOffset[std::size_t(side)] + count;
    }
    mValues.assign(std::size_t(mOffset[6]), mBase);
}

void OutsideAir::setInflows(std::span<const InflowPatch> active) {
    std::fill(mValues.begin(), mValues.end(), mBase);
    // The last patch first, so the first listed is written last and wins.
    for (auto patch = active.rbegin(); patch != active.rend(); ++patch) {
        const int axis = patch->side / 2;
        const auto [b, c] = alongSide(axis);
        std::array<int, 3> cell{0, 0, 0};
        for (cell[c] = 0; cell[c] < mGrid.cells[c]; ++cell[c])
            for (cell[b] = 0; cell[b] < mGrid.cells[b]; ++cell[b])
                if (patch->region.contains(sidePoint(patch->side, cell), mGrid))
                    mValues[std::size_t(ghostIndex(patch->side, cell))] = {
                        patch->density, patch->temperature, patch->fuel};
    }
}

std::int64_t OutsideAir::ghostIndex(int side, const std::array<int, 3>& cell) const {
    const auto [b, c] = alongSide(side / 2);
    return mOffset[std::size_t(side)] + cell[b] + std::int64_t(mGrid.cells[b]) * cell[c];
}

double OutsideAir::inBoxShare(const Vec3& g) const {
    double share = 1.0;
    for (int a = 0; a < mGrid.dim; ++a) {
        if (mSides[std::size_t(2 * a)]) share *= std::clamp(g[a] + 0.5, 0.0, 1.0);
        if (mSides[std::size_t(2 * a + 1)])
            share *= std::clamp(mGrid.cells[a] + 0.5 - g[a], 0.0, 1.0);
    }
    return share;
}

std::int64_t OutsideAir::ghostOf(const Vec3& g) const {
    int side = -1;
    double least = 2.0;
    for (int s = 0; s < 2 * mGrid.dim; ++s) {
        if (!mSides[std::size_t(s)]) continue;
        const int a = s / 2;
        const double inside = s % 2 ? mGrid.cells[a] + 0.5 - g[a] : g[a] + 0.5;
        if (std::clamp(inside, 0.0, 1.0) < least) {
            least = std::clamp(inside, 0.0, 1.0);
            side = s;
        }
    }
    if (side < 0) throw Error("outside air: no side lets air in");
    std::array<int, 3> cell{0, 0, 0};
    for (const int b : alongSide(side / 2)) {
        const int n = mGrid.cells[b];
        // A point far outside (a diverged trace) must not overflow the int.
        const double at = std::isfinite(g[b]) ? std::floor(g[b]) : 0.0;
        const int i = int(std::clamp(at, -double(n), 2.0 * n));
        cell[b] = mGrid.periodic[b] ? mGrid.wrap(b, i) : std::clamp(i, 0, n - 1);
    }
    return ghostIndex(side, cell);
}

double OutsideAir::value(std::int64_t ghost, std::optional<Field> field) const {
    return field ? mValues[std::size_t(ghost)][std::size_t(*field)] : 0.0;
}

std::vector<float> OutsideAir::texels() const {
    std::vector<float> texels(std::max<std::size_t>(1, mValues.size()) * 4, 0.0f);
    for (std::size_t g = 0; g < mValues.size(); ++g)
        for (std::size_t f = 0; f < 3; ++f) texels[4 * g + f] = float(mValues[g][f]);
    return texels;
}

Vec3 OutsideAir::sidePoint(int side, const std::array<int, 3>& cell) const {
    const int axis = side / 2;
    Vec3 point{0.0, 0.0, 0.0};
    for (int a = 0; a < mGrid.dim; ++a)
        point[a] = a == axis ? mGrid.origin[a] + (side % 2 ? mGrid.length(a) : 0.0)
                             : mGrid.cellCentre(a, cell[a]);
    return point;
}

std::int64_t OutsideAir::coveredFluidCells(const InflowPatch& patch,
                                           std::span<const std::uint8_t> fluidMask) const {
    const int axis = patch.side / 2;
    const auto [b, c] = alongSide(axis);
    std::array<int, 3> cell{0, 0, 0};
    cell[axis] = patch.side % 2 ? mGrid.cells[axis] - 1 : 0;
    std::int64_t covered = 0;
    for (cell[c] = 0; cell[c] < mGrid.cells[c]; ++cell[c])
        for (cell[b] = 0; cell[b] < mGrid.cells[b]; ++cell[b])
            covered += fluidMask[std::size_t(mGrid.cellIndex(cell[0], cell[1], cell[2]))] != 0 &&
                       patch.region.contains(sidePoint(patch.side, cell), mGrid);
    return covered;
}

void requireInflowsMeetFluid(const OutsideAir& outside, std::span<const InflowPatch> patches,
                             std::span<const std::uint8_t> fluidMask) {
    for (std::size_t p = 0; p < patches.size(); ++p) {
        const std::string name = "[[inflow]] #" + std::to_string(p + 1) + " (" +
                                 std::string(keywords::kSideNames[patches[p].side]) + ")";
        if (!outside.sides()[std::size_t(patches[p].side)])
            throw Error(name + ": no air comes in across that side");
        if (outside.coveredFluidCells(patches[p], fluidMask) == 0)
            throw Error(name +
                        ": its shape covers the centre of no fluid smoke cell's face on that "
                        "side; make it larger, or move it onto the fluid");
    }
}

}  // namespace modeflow
