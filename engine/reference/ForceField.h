#pragma once
/// @file ForceField.h
/// Grid forces on the velocity DOFs (engine/README.md, "Reduced dynamics"; engine/README.md), the
/// double-precision CPU reference of engine/device/ForceField: a force density g (force per unit
/// volume, along the face normal) on each DOF face, from buoyancy and stirring splats.
/// ForceProjection.h turns g into modal forces.
///
/// Buoyancy acts on the faces whose normal is up (+y in 2D, +z in 3D): g = buoyancy × the mean
/// temperature over the face's dual cell, the box reaching half a basis cell below and above
/// the face and covering the face across. On the smoke grid (scale s ≥ 1 smoke cells per basis
/// cell and axis) that box spans s smoke cells across per tangential axis and s along up: for
/// even s, s/2 whole smoke cells each side; for odd s, (s−1)/2 whole cells each side plus the
/// half of the smoke cell the face's plane cuts through on each end (weight ½). With a fluid mask
/// only fluid smoke cells count (the mean renormalized over them; 0 when none is fluid), so a
/// field that is 0 outside Ω does not weaken the force on faces next to a wall. A mask that marks
/// a smoke cell fluid when its basis cell has a part in Ω keeps a uniform temperature's force an
/// exact gradient (which projects to 0); without a mask, ~2–5% of it survives on the disk and
/// ball of ForceProjectionTest, with a cell-centre mask up to 2% at scale 1 (cut faces whose
/// dual cell holds no fluid smoke cell get g = 0).
///
/// A splat pushes with g = (force · n) exp(−|x − centre|² / radius²) at the face centre x,
/// n the face normal: the DOF faces of every axis get their component.
///
/// Periodic axes: the dual cell of an up-facing face on the seam reaches across it, and a splat
/// acts at the minimum-image distance (a splat past one end pushes near the other).

#include <cstdint>
#include <span>

#include <Eigen/Core>

#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/ForceSplat.h"

namespace modeflow::reference {

struct BuoyancyInput {
    double buoyancy = 0.0;                ///< upward acceleration per unit temperature
    int scale = 1;                        ///< smoke cells per basis cell and axis
    std::span<const double> temperature;  ///< one value per smoke cell; empty: no buoyancy
    std::span<const std::uint8_t>
        fluidMask;  ///< one per smoke cell, non-zero in Ω; empty: all count
};

/// Weighted mean of `temperature` over the dual cell of the up-facing face `face` (see above);
/// smoke cells outside the box are left out (across a periodic seam they are the other end's).
/// `mask` may be empty.
/// @throw modeflow::Error when `temperature` or a non-empty `mask` is not one value per smoke cell.
double dualCellTemperature(const MacGrid& basisGrid, int scale, const FaceLocation& face,
                           std::span<const double> temperature, std::span<const std::uint8_t> mask);

/// Σ over splats of (force · n) exp(−r²/radius²) at the centre of `face`.
double splatForce(const MacGrid& grid, const FaceLocation& face,
                  std::span<const ForceSplat> splats);

/// g on every DOF face (cache.faces order).
/// @throw modeflow::Error on a scale below 1, a temperature or mask that is not one value per
/// smoke cell, or a splat radius that is not positive.
Eigen::VectorXd forceDensity(const BasisCache& cache, const BuoyancyInput& buoyancy,
                             std::span<const ForceSplat> splats);

}  // namespace modeflow::reference
