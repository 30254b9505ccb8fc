#include "tests/support/SmokeTestFields.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace modeflow::testing {

MacGrid smokeTestGrid(int dim, int n) {
    MacGrid grid;
    grid.dim = dim;
    for (int a = 0; a < dim; ++a) {
        grid.cells[a] = n;
        grid.origin[a] = -1.0;
        grid.spacing[a] = 2.0 / n;
    }
    return grid;
}

Vec3 cellCentre(const MacGrid& grid, int x, int y, int z) {
    return {grid.cellCentre(0, x), grid.cellCentre(1, y),
            grid.dim == 3 ? grid.cellCentre(2, z) : 0.0};
}

std::vector<std::uint8_t> ballMask(const MacGrid& grid, double radius) {
    return cellValues<std::uint8_t>(grid, [radius](const Vec3& p) {
        return std::uint8_t(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] < radius * radius);
    });
}

FireSpec testFire() {
    FireSpec fire;
    fire.ignition = 1.0;
    fire.burnRate = 3.0;
    fire.heat = 2.0;
    fire.smoke = 0.25;
    return fire;
}

std::vector<std::uint8_t> wholeMask(const MacGrid& grid) {
    return std::vector<std::uint8_t>(std::size_t(grid.cellCount()), 1);
}

std::vector<double> gaussianBlob(const MacGrid& grid, const Vec3& centre, double sigma) {
    return cellValues<double>(grid, [&](const Vec3& p) {
        const Vec3 d = grid.minimumImage({p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]});
        double r2 = 0.0;
        for (int a = 0; a < 3; ++a) r2 += d[a] * d[a];
        return std::exp(-r2 / (2.0 * sigma * sigma));
    });
}

std::vector<double> constantVelocity(const MacGrid& grid, const Vec3& u) {
    std::vector<double> faces(std::size_t(grid.faceTotal()), 0.0);
    for (int axis = 0; axis < grid.dim; ++axis) {
        const std::array<int, 3> e = grid.faceExtent(axis);
        for (int z = 0; z < e[2]; ++z)
            for (int y = 0; y < e[1]; ++y)
                for (int x = 0; x < e[0]; ++x) {
                    const std::array<int, 3> p{x, y, z};
                    if (!grid.isWallFace(axis, p[axis]))
                        faces[grid.faceIndex(axis, x, y, z)] = u[axis];
                }
    }
    return faces;
}

std::vector<double> streamFunctionVelocity(const MacGrid& grid,
                                           const std::function<double(const Vec3&)>& psi) {
    const auto at = [&](int i, int j, int k) {
        return psi({grid.origin[0] + i * grid.spacing[0], grid.origin[1] + j * grid.spacing[1],
                    grid.dim == 3 ? grid.cellCentre(2, k) : 0.0});
    };
    std::vector<double> faces(std::size_t(grid.faceTotal()), 0.0);
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j <= grid.cells[1]; ++j)
            for (int i = 0; i <= grid.cells[0]; ++i) {
                // Along a periodic axis the faces at n are those at 0 (ψ repeats, so the same
                // value).
                if (j < grid.cells[1] && i < grid.faceExtent(0)[0])
                    faces[grid.faceIndex(0, i, j, k)] =
                        (at(i, j + 1, k) - at(i, j, k)) / grid.spacing[1];
                if (i < grid.cells[0] && j < grid.faceExtent(1)[1])
                    faces[grid.faceIndex(1, i, j, k)] =
                        -(at(i + 1, j, k) - at(i, j, k)) / grid.spacing[0];
            }
    return faces;
}

std::vector<double> rotationVelocity(const MacGrid& grid, double omega, double radius) {
    return streamFunctionVelocity(grid, [omega, radius](const Vec3& p) {
        const double r = std::min(std::hypot(p[0], p[1]), radius);
        return -0.5 * omega * r * r;
    });
}

std::vector<double> randomSwirlVelocity(const MacGrid& grid, double radius, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    std::vector<std::array<double, 6>> modes(6);
    for (auto& m : modes)
        for (double& c : m) c = coefficient(rng);
    return streamFunctionVelocity(grid, [&](const Vec3& p) {
        const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        if (r2 >= radius * radius) return 0.0;
        double sum = 0.0;
        for (const auto& m : modes)
            sum += m[0] *
                   std::sin(3.0 * m[1] * p[0] + 3.0 * m[2] * p[1] + 2.0 * m[3] * p[2] + m[4]) *
                   (1.0 + m[5]);
        const double envelope = (radius * radius - r2) / (radius * radius);
        return sum * envelope * envelope;
    });
}

std::vector<double> unitSwirlVelocity(const MacGrid& grid, double radius, std::uint64_t seed) {
    std::vector<double> faces = randomSwirlVelocity(grid, radius, seed);
    double peak = 0.0;
    for (const double v : faces) peak = std::max(peak, std::abs(v));
    for (double& v : faces) v /= peak;
    return faces;
}

std::vector<SmokeEmitter> smokeTestEmitters() {
    return {{EmitterShape::Ball, {0.25, -0.5, 0.125}, 0.3, {}, {}, 1.5, 0.75},
            {EmitterShape::Box, {}, 0.0, {-0.875, -0.3, -0.3}, {-0.5, 0.2, 0.2}, 0.5, 2.0}};
}

std::vector<float> mushroomCloud(const MacGrid& grid) {
    return cellValues<float>(grid, [](const Vec3& p) {
        const double x = p[0], y = p[1], z = p[2];
        const double sx = x - 0.06 * std::sin(7.0 * z), stem = sx * sx + y * y;
        const double ring = std::pow(std::hypot(x, y) - 0.3, 2) + (z - 0.3) * (z - 0.3);
        const double cap = x * x + y * y + (z - 0.4) * (z - 0.4);
        return float(0.5 * std::exp(-stem / 0.01) * std::clamp((0.3 - z) / 0.2, 0.0, 1.0) *
                         (0.8 + 0.2 * std::sin(23.0 * z)) +
                     std::exp(-ring / 0.012) + 0.6 * std::exp(-cap / 0.03));
    });
}

const char* schemeName(AdvectionScheme scheme) {
    return scheme == AdvectionScheme::SemiLagrangian ? "semi-Lagrangian"
           : scheme == AdvectionScheme::MacCormack   ? "MacCormack"
                                                     : "conservative";
}

Vec3 centroid(const MacGrid& grid, const std::vector<double>& field) {
    return centroidNear(grid, field, {0.0, 0.0, 0.0});
}

Vec3 centroidNear(const MacGrid& grid, const std::vector<double>& field, const Vec3& around) {
    Vec3 moment{0.0, 0.0, 0.0};
    double total = 0.0;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double v = field[grid.cellIndex(x, y, z)];
                const Vec3 p = grid.nearestImage(cellCentre(grid, x, y, z), around);
                for (int a = 0; a < 3; ++a) moment[a] += v * p[a];
                total += v;
            }
    for (double& m : moment) m /= total;
    return moment;
}

MacGrid periodicSmokeTestGrid(int dim, int n) {
    MacGrid grid = smokeTestGrid(dim, n);
    grid.periodic = {true, true, dim == 3};
    return grid;
}

std::vector<double> diagonalFlow(const MacGrid& grid) {
    return constantVelocity(grid, {2.0, 2.0, grid.dim == 3 ? 2.0 : 0.0});
}

}  // namespace modeflow::testing
