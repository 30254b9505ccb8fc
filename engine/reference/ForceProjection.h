#pragma once
/// @file ForceProjection.h
/// Grid forces → modal forces f_k = Ψ_kᵀ ⋆ F (engine/README.md, "Reduced dynamics"), the
/// double-precision CPU reference of engine/device/ForceProjection. Both inputs reduce to f_k = Σ_d
/// Ψ_k[d] w_d q_d with a weight per DOF that depends on what q is:
///
/// - a force density g (force per volume along the normal, ForceField.h): F = g |f ∩ Ω| and
///   ⋆ = |dual edge| / |f ∩ Ω|, so ⋆F = g |dual edge| = g h_axis (h_axis the spacing along the
///   normal; DOFs never lie on the box, so their dual edges are whole);
/// - a face-field value u (MacGrid.h: flux over the whole face area A): F = u A, ⋆F = u A ⋆.
///   This is the exact inverse of the reconstruction: projecting the face field of Σ v_i Ψ_i
///   gives v back (⋆-orthonormality).
///
/// The two agree where a face is whole; on cut faces a density is spread over the fluid part
/// only (|f ∩ Ω| = A × fraction ≤ A), a face-field value over the whole face.

#include <span>

#include <Eigen/Core>

#include "engine/basis/VelocityBasis.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/ProjectionWeights.h"

namespace modeflow::reference {

/// f_k = Σ_d Ψ_k[d] w_d q_d, q given per DOF (cache.faces order); by the transposed separable
/// transforms for a closed-form basis.
/// @throw modeflow::Error when q is not one value per DOF.
Eigen::VectorXd projectForce(const VelocityBasis& basis, const Eigen::VectorXd& q,
                             FaceQuantity quantity);
/// The same through a VelocityBasis made for the call.
Eigen::VectorXd projectForce(const BasisCache& cache, const Eigen::VectorXd& q,
                             FaceQuantity quantity);

/// projectForce of a whole-grid face field (MacGrid face numbering), read on the DOF faces.
/// @throw modeflow::Error when the field is not one value per face of the cache's grid.
Eigen::VectorXd projectFaceField(const VelocityBasis& basis, std::span<const double> faceField);
Eigen::VectorXd projectFaceField(const BasisCache& cache, std::span<const double> faceField);

}  // namespace modeflow::reference
