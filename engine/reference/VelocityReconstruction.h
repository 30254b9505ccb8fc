#pragma once
/// @file VelocityReconstruction.h
/// Modal velocity → grid velocity (engine/README.md), the double-precision CPU reference of
/// engine/device/VelocityReconstruction: the fluxes Ψ v on the basis's face DOFs turned into a
/// face field of the whole grid (MacGrid.h: flux / full face area, 0 on faces that are not
/// DOFs), and cell-centred velocities for output.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/basis/VelocityBasis.h"
#include "engine/core/MacGrid.h"
#include "engine/format/BasisCache.h"

namespace modeflow::reference {

/// u[cache.faces[d]] = fluxes[d] / faceArea(axis of the face); every other face 0.
/// @throw modeflow::Error when `fluxes` is not one value per DOF or a DOF is not a grid face.
std::vector<double> fluxesToFaceField(const BasisCache& cache, const Eigen::VectorXd& fluxes);

/// The face field of Σ_i v_i Ψ_i (by the separable transforms for a closed-form basis).
/// @throw modeflow::Error when v is not one value per mode.
std::vector<double> reconstructFaceField(const VelocityBasis& basis, const Eigen::VectorXd& v);
/// The same through a VelocityBasis made for the call.
std::vector<double> reconstructFaceField(const BasisCache& cache, const Eigen::VectorXd& v);

/// Velocity at every cell centre (cellIndex order): per axis the mean of the cell's two faces
/// (2D: third component 0). Cheap and first-order; for the VDB `vel` grid.
/// @throw modeflow::Error when `faceField` is not one value per face of `grid`.
std::vector<Vec3> cellCentreVelocity(const MacGrid& grid, std::span<const double> faceField);

/// Per cell, the net outflow Σ_faces ±u·area of a face field (0 for a divergence-free field).
/// @throw modeflow::Error when `faceField` is not one value per face of `grid`.
std::vector<double> faceFieldDivergence(const MacGrid& grid, std::span<const double> faceField);

}  // namespace modeflow::reference
