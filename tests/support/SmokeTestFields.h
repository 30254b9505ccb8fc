#pragma once
/// @file SmokeTestFields.h
/// Grids, fluid masks, velocity face fields and smoke fields for the smoke and preview tests and
/// tools/bench:
/// divergence-free velocities come from a stream function ψ on the grid's z-edges (2D: its
/// vertices), whose discrete curl (u = ∂ψ/∂y, v = −∂ψ/∂x, face by face) has zero discrete
/// divergence exactly.

#include <cstdint>
#include <functional>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/core/SceneSpec.h"
#include "engine/simulation/SmokeEmitter.h"

namespace modeflow::testing {

/// [−1, 1]^dim with n cells per axis.
MacGrid smokeTestGrid(int dim, int n);

/// The centre of cell (x, y, z) (the third coordinate 0 in 2D).
Vec3 cellCentre(const MacGrid& grid, int x, int y, int z);

/// One value per cell of `f` at its centre.
template <typename T>
std::vector<T> cellValues(const MacGrid& grid, const std::function<T(const Vec3&)>& f) {
    std::vector<T> values(std::size_t(grid.cellCount()));
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x)
                values[grid.cellIndex(x, y, z)] = f(cellCentre(grid, x, y, z));
    return values;
}

/// 1 on cells whose centre lies within `radius` of the origin (a disk or a ball).
std::vector<std::uint8_t> ballMask(const MacGrid& grid, double radius);

std::vector<std::uint8_t> wholeMask(const MacGrid& grid);

/// The fire of the burn tests: ignition 1, burn rate 3, heat 2, smoke 0.25.
FireSpec testFire();

/// A Gaussian bump of height 1 and width σ around `centre` (at the minimum-image distance along
/// periodic axes, so a bump near the seam continues across it).
std::vector<double> gaussianBlob(const MacGrid& grid, const Vec3& centre, double sigma);

/// `u` on every interior face of each axis (the seam's faces on a periodic axis), 0 on the walls
/// of the box.
std::vector<double> constantVelocity(const MacGrid& grid, const Vec3& u);

/// The discrete curl of ψ(x, y, z) sampled on z-edges (x_i, y_j, centre of layer k): exactly
/// divergence-free; the walls get zero flux when ψ is constant along the box's boundary. Along a
/// periodic axis ψ must repeat (the seam's faces are taken at position 0).
std::vector<double> streamFunctionVelocity(const MacGrid& grid,
                                           const std::function<double(const Vec3&)>& psi);

/// Rigid rotation at angular speed ω about the z axis inside radius R, at rest outside
/// (ψ = −ω min(r, R)² / 2, r the distance to the z axis).
std::vector<double> rotationVelocity(const MacGrid& grid, double omega, double radius);

/// A random smooth swirl about z confined to the disk (ball) of radius R: ψ a few random
/// Fourier modes times (1 − r²/R²)² inside, 0 outside, so no flux leaves the disk (ball).
std::vector<double> randomSwirlVelocity(const MacGrid& grid, double radius, std::uint64_t seed);

/// randomSwirlVelocity scaled to max |face value| = 1.
std::vector<double> unitSwirlVelocity(const MacGrid& grid, double radius, std::uint64_t seed);

/// Two emitters in [−1, 1]^dim: a ball and a box, each with its own density and temperature rates.
std::vector<SmokeEmitter> smokeTestEmitters();

/// A mushroom cloud about the origin of [−1, 1]³: a wavy stem under a ring and a cap.
std::vector<float> mushroomCloud(const MacGrid& grid);

inline constexpr AdvectionScheme kAdvectionSchemes[] = {AdvectionScheme::SemiLagrangian,
                                                        AdvectionScheme::MacCormack};

const char* schemeName(AdvectionScheme scheme);

/// Σ φ·x / Σ φ over the cells: a smoke field's centre of mass, in scene coordinates.
Vec3 centroid(const MacGrid& grid, const std::vector<double>& field);

/// The centroid of the field's images nearest `around` along periodic axes (the field must be
/// small beside the box for that to mean much); `centroid` on other axes.
Vec3 centroidNear(const MacGrid& grid, const std::vector<double>& field, const Vec3& around);

/// smokeTestGrid periodic along every axis (a torus), and the uniform flow (2, 2[, 2]) that
/// crosses it along each axis in time 1: a harmonic field of the torus.
MacGrid periodicSmokeTestGrid(int dim, int n);
std::vector<double> diagonalFlow(const MacGrid& grid);

}  // namespace modeflow::testing
