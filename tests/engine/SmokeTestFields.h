#pragma once
/// @file SmokeTestFields.h
/// Grids, fluid masks, velocity face fields and smoke fields for the smoke advection tests:
/// divergence-free velocities come from a stream function ψ on the grid's z-edges (2D: its
/// vertices), whose discrete curl (u = ∂ψ/∂y, v = −∂ψ/∂x, face by face) has zero discrete
/// divergence exactly.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/reference/SmokeAdvection.h"

namespace modeflow::testing {

/// [−1, 1]^dim with n cells per axis.
inline MacGrid smokeTestGrid(int dim, int n) {
    MacGrid grid;
    grid.dim = dim;
    for (int a = 0; a < dim; ++a) {
        grid.cells[a] = n;
        grid.origin[a] = -1.0;
        grid.spacing[a] = 2.0 / n;
    }
    return grid;
}

inline Vec3 cellCentre(const MacGrid& grid, int x, int y, int z) {
    return {grid.cellCentre(0, x), grid.cellCentre(1, y), grid.dim == 3 ? grid.cellCentre(2, z) : 0.0};
}

/// One value per cell of `f` at its centre (the third coordinate 0 in 2D).
template <typename T>
std::vector<T> cellValues(const MacGrid& grid, const std::function<T(const Vec3&)>& f) {
    std::vector<T> values(std::size_t(grid.cellCount()));
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) values[grid.cellIndex(x, y, z)] = f(cellCentre(grid, x, y, z));
    return values;
}

/// 1 on cells whose centre lies within `radius` of the origin (a disk or a ball).
inline std::vector<std::uint8_t> ballMask(const MacGrid& grid, double radius) {
    return cellValues<std::uint8_t>(grid, [radius](const Vec3& p) {
        return std::uint8_t(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] < radius * radius);
    });
}

inline std::vector<std::uint8_t> wholeMask(const MacGrid& grid) {
    return std::vector<std::uint8_t>(std::size_t(grid.cellCount()), 1);
}

/// A Gaussian bump of height 1 and width σ around `centre`.
inline std::vector<double> gaussianBlob(const MacGrid& grid, const Vec3& centre, double sigma) {
    return cellValues<double>(grid, [&](const Vec3& p) {
        double r2 = 0.0;
        for (int a = 0; a < 3; ++a) r2 += (p[a] - centre[a]) * (p[a] - centre[a]);
        return std::exp(-r2 / (2.0 * sigma * sigma));
    });
}

/// `u` on every interior face of each axis, 0 on the walls of the box.
inline std::vector<double> constantVelocity(const MacGrid& grid, const Vec3& u) {
    std::vector<double> faces(std::size_t(grid.faceTotal()), 0.0);
    for (int axis = 0; axis < grid.dim; ++axis) {
        const std::array<int, 3> e = grid.faceExtent(axis);
        for (int z = 0; z < e[2]; ++z)
            for (int y = 0; y < e[1]; ++y)
                for (int x = 0; x < e[0]; ++x) {
                    const std::array<int, 3> p{x, y, z};
                    if (p[axis] > 0 && p[axis] < grid.cells[axis]) faces[grid.faceIndex(axis, x, y, z)] = u[axis];
                }
    }
    return faces;
}

/// The discrete curl of ψ(x, y, z) sampled on z-edges (x_i, y_j, centre of layer k): exactly
/// divergence-free; the walls get zero flux when ψ is constant along the box's boundary.
inline std::vector<double> streamFunctionVelocity(const MacGrid& grid, const std::function<double(const Vec3&)>& psi) {
    const auto at = [&](int i, int j, int k) {
        return psi({grid.origin[0] + i * grid.spacing[0], grid.origin[1] + j * grid.spacing[1],
                    grid.dim == 3 ? grid.cellCentre(2, k) : 0.0});
    };
    std::vector<double> faces(std::size_t(grid.faceTotal()), 0.0);
    for (int k = 0; k < grid.cells[2]; ++k)
        for (int j = 0; j <= grid.cells[1]; ++j)
            for (int i = 0; i <= grid.cells[0]; ++i) {
                if (j < grid.cells[1])
                    faces[grid.faceIndex(0, i, j, k)] = (at(i, j + 1, k) - at(i, j, k)) / grid.spacing[1];
                if (i < grid.cells[0])
                    faces[grid.faceIndex(1, i, j, k)] = -(at(i + 1, j, k) - at(i, j, k)) / grid.spacing[0];
            }
    return faces;
}

/// Rigid rotation at angular speed ω about the z axis inside radius R, at rest outside
/// (ψ = −ω min(r, R)² / 2, r the distance to the z axis).
inline std::vector<double> rotationVelocity(const MacGrid& grid, double omega, double radius) {
    return streamFunctionVelocity(grid, [omega, radius](const Vec3& p) {
        const double r = std::min(std::hypot(p[0], p[1]), radius);
        return -0.5 * omega * r * r;
    });
}

/// A random smooth swirl about z confined to the disk (ball) of radius R: ψ a few random
/// Fourier modes times (1 − r²/R²)² inside, 0 outside, so no flux leaves the disk (ball).
inline std::vector<double> randomSwirlVelocity(const MacGrid& grid, double radius, std::uint64_t seed) {
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
            sum += m[0] * std::sin(3.0 * m[1] * p[0] + 3.0 * m[2] * p[1] + 2.0 * m[3] * p[2] + m[4]) * (1.0 + m[5]);
        const double envelope = (radius * radius - r2) / (radius * radius);
        return sum * envelope * envelope;
    });
}

/// randomSwirlVelocity scaled to max |face value| = 1.
inline std::vector<double> unitSwirlVelocity(const MacGrid& grid, double radius, std::uint64_t seed) {
    std::vector<double> faces = randomSwirlVelocity(grid, radius, seed);
    double peak = 0.0;
    for (const double v : faces) peak = std::max(peak, std::abs(v));
    for (double& v : faces) v /= peak;
    return faces;
}

inline constexpr AdvectionScheme kAdvectionSchemes[] = {AdvectionScheme::SemiLagrangian, AdvectionScheme::MacCormack};

inline const char* schemeName(AdvectionScheme scheme) {
    return scheme == AdvectionScheme::SemiLagrangian ? "semi-Lagrangian" : "MacCormack";
}

/// Σ φ·x / Σ φ over the cells.
inline Vec3 centroid(const MacGrid& grid, const std::vector<double>& field) {
    Vec3 moment{0.0, 0.0, 0.0};
    double total = 0.0;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double v = field[grid.cellIndex(x, y, z)];
                const Vec3 p = cellCentre(grid, x, y, z);
                for (int a = 0; a < 3; ++a) moment[a] += v * p[a];
                total += v;
            }
    for (double& m : moment) m /= total;
    return moment;
}

}  // namespace modeflow::testing
