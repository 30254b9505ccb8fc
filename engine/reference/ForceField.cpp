#include "engine/reference/ForceField.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/Error.h"

namespace modeflow::reference {
namespace {

/// Smoke cells [begin, end) along one axis with the weight of the two end cells.
struct AxisRange {
    int begin = 0;
    int end = 1;
    double endWeight = 1.0;
};

AxisRange dualRange(const FaceLocation& face, int axis, int scale, int up) {
    if (axis != up) return {face.pos[axis] * scale, (face.pos[axis] + 1) * scale, 1.0};
    // [p s − s/2, p s + s/2] in smoke-cell units: ⌈s/2⌉ cells each side, the end ones halved for
    // odd s.
    const int half = (scale + 1) / 2;
    return {face.pos[axis] * scale - half, face.pos[axis] * scale + half, scale % 2 ? 0.5 : 1.0};
}

void requireSmokeField(std::size_t size, std::int64_t cells, const char* what) {
    if (size != std::size_t(cells))
        throw Error(std::string("force field: the ") + what + " has " + std::to_string(size) +
                    " values, the smoke grid " + std::to_string(cells) + " cells");
}

}  // namespace

double dualCellTemperature(const MacGrid& basisGrid, int scale, const FaceLocation& face,
                           std::span<const double> temperature,
                           std::span<const std::uint8_t> mask) {
    const MacGrid smoke = basisGrid.refined(scale);
    requireSmokeField(temperature.size(), smoke.cellCount(), "temperature");
    if (!mask.empty()) requireSmokeField(mask.size(), smoke.cellCount(), "fluid mask");
    const int up = upAxis(basisGrid);
    std::array<AxisRange, 3> range{};
    for (int a = 0; a < basisGrid.dim; ++a) range[a] = dualRange(face, a, scale, up);
    // Along a periodic up axis the dual cell of a face on the seam wraps to the other end;
    // elsewhere cells past the box are left out.
    const auto inBox = [&](int axis, int position) {
        const int wrapped = smoke.wrap(axis, position);
        return wrapped >= 0 && wrapped < smoke.cells[axis] ? wrapped : -1;
    };
    double sum = 0.0, weight = 0.0;
    for (int rz = range[2].begin; rz < range[2].end; ++rz)
        for (int ry = range[1].begin; ry < range[1].end; ++ry)
            for (int rx = range[0].begin; rx < range[0].end; ++rx) {
                const int x = inBox(0, rx), y = inBox(1, ry), z = inBox(2, rz);
                if (x < 0 || y < 0 || z < 0) continue;
                const std::int64_t c = smoke.cellIndex(x, y, z);
                if (!mask.empty() && !mask[std::size_t(c)]) continue;
                const int along = up == 1 ? ry : rz;
                const double w = along == range[up].begin || along == range[up].end - 1
                                     ? range[up].endWeight
                                     : 1.0;
                sum += w * temperature[std::size_t(c)];
                weight += w;
            }
    return weight > 0.0 ? sum / weight : 0.0;
}

double splatForce(const MacGrid& grid, const FaceLocation& face,
                  std::span<const ForceSplat> splats) {
    const Vec3 x = faceCentre(grid, face);
    double g = 0.0;
    for (const ForceSplat& splat : splats) {
        const Vec3 d = grid.minimumImage(
            {x[0] - splat.centre[0], x[1] - splat.centre[1], x[2] - splat.centre[2]});
        double r2 = 0.0;
        for (int a = 0; a < grid.dim; ++a) r2 += d[a] * d[a];
        g += splat.force[face.axis] * std::exp(-r2 / (splat.radius * splat.radius));
    }
    return g;
}

Eigen::VectorXd forceDensity(const BasisCache& cache, const BuoyancyInput& buoyancy,
                             std::span<const ForceSplat> splats) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const std::int64_t smokeCells = grid.refined(buoyancy.scale).cellCount();  // checks the scale
    const bool buoyant = !buoyancy.temperature.empty() && buoyancy.buoyancy != 0.0;
    if (!buoyancy.temperature.empty())
        requireSmokeField(buoyancy.temperature.size(), smokeCells, "temperature");
    if (!buoyancy.fluidMask.empty())
        requireSmokeField(buoyancy.fluidMask.size(), smokeCells, "fluid mask");
    for (const ForceSplat& splat : splats)
        if (!(splat.radius > 0.0))
            throw Error("force field: a splat radius must be positive, got " +
                        std::to_string(splat.radius));

    Eigen::VectorXd g(Eigen::Index(cache.faces.size()));
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const FaceLocation face = locateFace(grid, cache.faces[d]);
        double value = splatForce(grid, face, splats);
        if (buoyant && face.axis == upAxis(grid))
            value +=
                buoyancy.buoyancy * dualCellTemperature(grid, buoyancy.scale, face,
                                                        buoyancy.temperature, buoyancy.fluidMask);
        g[Eigen::Index(d)] = value;
    }
    return g;
}

}  // namespace modeflow::reference
