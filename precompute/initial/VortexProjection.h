#pragma once
/// @file VortexProjection.h
/// Analytic velocity fields → modal state on a cached basis. The basis stores ⋆-orthonormal face
/// fluxes Ψ, so a flux field F projects as v_k = Σ_f Ψ_k(f) ⋆_f F_f: the ⋆-inner product with
/// each mode, exact (a round trip) for fields in the span of the basis.

#include <functional>
#include <span>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

using VelocityField = std::function<Vec3(const Vec3&)>;

/// Segments of the discretized ring centre line in the 3D Biot–Savart sum.
inline constexpr int kRingSegments = 128;

/// Velocity of the summed vortices at x on `grid` (its dim, and its periodic axes). 2D (x[2]
/// ignored): Lamb–Oseen vortices, u = Γ/(2π r²)(1 − exp(−r²/σ²)) (−y', x'), counter-clockwise for
/// Γ > 0. 3D: vortex rings by the Biot–Savart integral over kRingSegments chords with
/// Rosenhead–Moore core σ, u = Γ/4π Σ dl × (x − p) / (|x − p|² + σ²)^{3/2}, the ring turning
/// right-handedly about its normal (so it travels along +normal for Γ > 0). Along a periodic axis
/// a vortex acts with its periodic images (2D: their sum in closed form; 3D: each chord's image
/// nearest x), so the field wraps the seams: a vortex centred on a seam is the same vortex as one
/// in the middle of the grid.
Vec3 vortexVelocity(std::span<const VortexSpec> vortices, const GridSpec& grid, const Vec3& x);

/// Fluxes F_f = ∫_{f∩Ω} u·n of u through the cache's face DOFs (`cache.faces` order): the mean of
/// u·n by a Gauss rule (2 points per tangential axis) over the whole face times |f ∩ Ω|, which is
/// dualMeasure / faceStar.
Eigen::VectorXd faceFluxes(const BasisCache& cache, const VelocityField& u);

/// v_k = Σ_f Ψ_k(f) ⋆_f F_f for every velocity mode. @throw Error when F has the wrong size.
Eigen::VectorXd projectFluxes(const BasisCache& cache, const Eigen::VectorXd& fluxes);

/// The vortices' summed field projected on the basis, rescaled to ½|v|² = energy when energy > 0.
/// @throw Error naming [initial] when there are no vortices, or when a rescale is asked for and
/// the projection vanishes (vortices outside the domain, or finer than the basis resolves).
Eigen::VectorXd projectVortices(const BasisCache& cache, std::span<const VortexSpec> vortices,
                                double energy);

}  // namespace modeflow
