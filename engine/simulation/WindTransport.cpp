#include "engine/simulation/WindTransport.h"

#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacSampling.h"

namespace modeflow {
namespace {

/// The axes the wind blows along (non-zero components).
std::vector<int> windAxes(const MacGrid& grid, const Vec3& wind) {
    std::vector<int> axes;
    for (int a = 0; a < grid.dim; ++a)
        if (wind[a] != 0.0) axes.push_back(a);
    return axes;
}

/// Calls visit(face, position) for every face normal to `normal`.
template <typename Visit>
void forEachFace(const MacGrid& grid, int normal, Visit&& visit) {
    const std::array<int, 3> extent = grid.faceExtent(normal);
    for (int z = 0; z < extent[2]; ++z)
        for (int y = 0; y < extent[1]; ++y)
            for (int x = 0; x < extent[0]; ++x)
                visit(grid.faceIndex(normal, x, y, z), std::array<int, 3>{x, y, z});
}

}  // namespace

WindTransport::WindTransport(const BasisCache& cache, const Vec3& wind)
    : mCache(cache), mBasis(cache), mGrid(MacGrid::fromSpec(cache.grid)), mWind(wind) {
    if (cache.kind != BasisKind::Grid) throw Error("wind: a surface basis has no wind");
    for (const double u : wind)
        if (!std::isfinite(u)) throw Error("wind: the velocity is not finite");
    for (const std::int64_t face : cache.faces)
        if (face < 0 || face >= mGrid.faceTotal())
            throw Error("wind: face DOF " + std::to_string(face) + " is not a face of the grid");
}

std::vector<double> WindTransport::gridFluxes(const Eigen::VectorXd& v) const {
    const Eigen::VectorXd dofFluxes = mBasis.fluxes(v);
    std::vector<double> fluxes(std::size_t(mGrid.faceTotal()), 0.0);
    for (std::size_t d = 0; d < mCache.faces.size(); ++d)
        fluxes[std::size_t(mCache.faces[d])] = dofFluxes[Eigen::Index(d)];
    return fluxes;
}

void WindTransport::apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    const std::vector<double> fluxes = gridFluxes(v);
    std::vector<double> change(fluxes.size(), 0.0);
    for (const int a : windAxes(mGrid, mWind)) {
        const double u = mWind[a];
        const double scale = -u / (2.0 * mGrid.spacing[a]);
        for (int c = 0; c < mGrid.dim; ++c) {
            const int last = mGrid.faceExtent(c)[a] - 1;
            forEachFace(mGrid, c, [&](std::int64_t face, std::array<int, 3> p) {
                // The lattice's value at position q along a: wrapped on a periodic axis; beyond
                // the box, 0 upstream (the undisturbed inflow) and the last value downstream.
                const auto at = [&](int q) {
                    if (mGrid.periodic[a]) q = (q + last + 1) % (last + 1);
                    if (q < 0 || q > last) {
                        const bool downstream = (q > last) == (u > 0.0);
                        if (!downstream) return 0.0;
                        q = q < 0 ? 0 : last;
                    }
                    std::array<int, 3> n = p;
                    n[a] = q;
                    return fluxes[std::size_t(mGrid.faceIndex(c, n[0], n[1], n[2]))];
                };
                change[std::size_t(face)] += scale * (at(p[a] + 1) - at(p[a] - 1));
            });
        }
    }
    Eigen::VectorXd starred(Eigen::Index(mCache.faces.size()));
    for (std::size_t d = 0; d < mCache.faces.size(); ++d)
        starred[Eigen::Index(d)] =
            mCache.faceStar[Eigen::Index(d)] * change[std::size_t(mCache.faces[d])];
    out = mBasis.transposed(starred);
}

const Eigen::MatrixXd& WindTransport::matrix() const {
    if (mMatrix.size() == 0) {
        const int n = size();
        Eigen::MatrixXd d(n, n);
        Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column;
        for (int j = 0; j < n; ++j) {
            unit[j] = 1.0;
            apply(unit, column);
            d.col(j) = column;
            unit[j] = 0.0;
        }
        mMatrix = std::move(d);
    }
    return mMatrix;
}

double WindTransport::outflowPower(const Eigen::VectorXd& v) const {
    const std::vector<double> fluxes = gridFluxes(v);
    double power = 0.0;
    for (const int a : windAxes(mGrid, mWind)) {
        if (mGrid.periodic[a]) continue;
        const double sideArea = mGrid.cellVolume() / mGrid.spacing[a];  // of one cell's side
        for (int c = 0; c < mGrid.dim; ++c) {
            if (c == a) continue;  // the walls along a: no disturbance crosses them
            const int downstream = mWind[a] > 0.0 ? mGrid.faceExtent(c)[a] - 1 : 0;
            forEachFace(mGrid, c, [&](std::int64_t face, std::array<int, 3> p) {
                if (p[a] != downstream) return;
                const double velocity = fluxes[std::size_t(face)] / mGrid.faceArea(c);
                power += 0.5 * std::abs(mWind[a]) * velocity * velocity * sideArea;
            });
        }
    }
    return power;
}

SimulationSettings withWindTransport(SimulationSettings settings, const BasisCache& cache) {
    if (settings.wind)
        settings.fluid.linear = std::make_shared<WindTransport>(cache, *settings.wind);
    return settings;
}

MacGrid withWindThrough(MacGrid grid, const Vec3& wind) {
    for (const int a : windAxes(grid, wind)) grid.flowThrough[a] = !grid.periodic[a];
    return grid;
}

std::array<int, 3> inflowSides(const MacGrid& grid, const Vec3& wind) {
    std::array<int, 3> sides{0, 0, 0};
    for (int a = 0; a < grid.dim; ++a)
        if (!grid.periodic[a] && wind[a] != 0.0) sides[a] = wind[a] > 0.0 ? -1 : 1;
    return sides;
}

MacGrid airGridOf(const GridSpec& spec, const std::optional<Vec3>& wind) {
    const MacGrid grid = MacGrid::fromSpec(spec);
    return wind ? withWindThrough(grid, *wind) : grid;
}

void addWind(const MacGrid& grid, const Vec3& wind, std::span<double> faceField) {
    requireFaceField(grid, faceField.size(), "wind face field");
    for (const int a : windAxes(grid, wind))
        forEachFace(grid, a, [&](std::int64_t face, std::array<int, 3>) {
            faceField[std::size_t(face)] += wind[a];
        });
}

}  // namespace modeflow
