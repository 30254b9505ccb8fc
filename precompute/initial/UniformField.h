#pragma once
/// @file UniformField.h
/// The initial magnetic field of the MHD rotor test (seed Fig. 6.18): uniform, left to right, in
/// the velocity basis (seed §6.3.5 puts F in the same divergence-free basis as v).
///
/// A field tangent to the wall cannot be uniform all the way to it: a uniform B0 is the gradient
/// of B0·x, and gradients are ⋆-orthogonal to every divergence-free mode with zero normal flux,
/// so its projection on the basis vanishes (to discretization error). What is uniform in the
/// interior and representable is the curl of a vector potential that fades out at the wall:
///
///     B = ∇×(w A) = w B0 + ∇w × A,   ∇×A = B0,   w = smoothstep(d(x) / L),
///
/// with d the distance to the wall (Ω's χ and the grid box's walls: not the ends of a periodic
/// axis, where the field goes on) and A = ½ B0 × (x − c) (3D), or
/// A = (B0ₓ(y − c_y) − B0_y(x − c_x)) ẑ (2D), about Ω's centroid c. With periodic axes A takes
/// for each component of B0 a gauge that does not grow along them (B0_a ê_a = ∇×(r_b ê_c) or
/// ∇×(−r_c ê_b)), so B wraps the seams; a component across walls whose cross-section closes on
/// itself through periodic axes is refused (no such field crosses it on average). B is
/// divergence-free, equals B0 where d ≥ L, and has zero normal flux through the wall (w = 0 there);
/// the flux B0 carries across Ω returns along the wall within the layer L. It is projected on the
/// basis exactly as vortex velocities are (VortexProjection.h: face fluxes, then the ⋆-inner
/// product).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"
#include "precompute/geometry/Domain.h"

namespace modeflow {

/// The default layer L the field turns in (`magnetic_wall_layer` overrides it): one wavelength
/// 2π/κ of the basis's highest mode, the narrowest the basis resolves. The field is no
/// equilibrium in the layer (its lines turn at the walls), and the motion that starts there
/// shrinks as L grows (scenes/README.md, "Scene files").
/// @throw Error for a basis without modes.
double uniformFieldLayer(const BasisCache& cache);

/// B at x (above) for the domain `shapes` (empty: the whole grid box) of the cache's grid.
class UniformField {
public:
    /// @throw Error for a zero `direction`, a non-positive `layer`, a direction across walls
    /// whose cross-section is periodic all round, or a domain shape that cannot be built.
    UniformField(const BasisCache& cache, const std::vector<ShapeSpec>& shapes,
                 const Vec3& direction, double strength, double layer);
    Vec3 operator()(const Vec3& x) const;

private:
    /// Sets mPotential (and mWrapped): see the file comment.
    void choosePotential();
    double wallDistance(const Vec3& x) const;
    /// w(x), the weight of the uniform part.
    double weight(const Vec3& x) const;

    GridSpec mGrid;
    Domain mDomain;
    Vec3 mField{0.0, 0.0, 0.0};   ///< B0
    Vec3 mCentre{0.0, 0.0, 0.0};  ///< c
    double mLayer = 1.0;
    std::array<Vec3, 3> mPotential{};  ///< A_i = Σ_j mPotential[i][j] (x − c)_j
    std::array<bool, 3> mWrapped{false, false,
                                 false};  ///< coordinates taken at their nearest image
};

/// UniformField projected on the basis: v_k = Σ_f Ψ_k(f) ⋆_f F_f of its face fluxes.
Eigen::VectorXd projectUniformField(const BasisCache& cache, const UniformField& field);

}  // namespace modeflow
