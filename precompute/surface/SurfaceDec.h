#pragma once
/// @file SurfaceDec.h
/// Discrete exterior calculus on a closed triangle surface (precompute/README.md, "Surfaces"):
/// primal vertices, edges and triangles, their incidence d0, d1 and diagonal Hodge stars.
///
/// The velocity is a 1-form on primal edges stored as a *flux*, as on grids: F_e is the flux
/// across edge a→b (a < b) towards its left seen from outside, i.e. along n × (b − a). Then
///   divergence-free  ⇔ d1 F = 0 (each triangle's d1 row sums the fluxes into it),
///   stream function  F = d0 ψ  (ψ on vertices; u = n × ∇ψ),
///   vorticity        ω = −⋆0⁻¹ d0ᵀ ⋆1 F at vertices (= Δψ for F = d0 ψ).
///
/// ⋆1 is the circumcentric (cotan) star, ⋆1(e) = (cot α + cot β)/2 over the two angles facing
/// e: d0ᵀ⋆1d0 is then exactly the stiffness matrix of linear finite elements, so the
/// Laplace–Beltrami operator is symmetric positive semi-definite with the constants as its only
/// null space whatever the angles, and Fᵀ⋆1F equals Σ_t A_t|u_t|² — the L² energy of the
/// face-wise constant velocity — for every F with d1 F = 0. An obtuse triangle makes the weight
/// of the edge facing its obtuse angle smaller, and negative when the two angles facing an edge
/// sum to more than π. Such weights are kept as they are: clamping them would break both
/// identities. They never make an energy negative, since velocities are divergence-free, and
/// nothing divides by ⋆1 (the harmonic forms come from cohomology, not from an eigenproblem with
/// ⋆1 as its mass). ⋆0 is barycentric (a third of each adjacent triangle's area: positive on
/// any mesh), ⋆2 is 1/area.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "engine/core/TriangleMesh.h"
#include "precompute/surface/SurfaceTopology.h"

namespace modeflow {

struct SurfaceDec {
    using Sparse = Eigen::SparseMatrix<double>;
    SurfaceTopology topology;
    Sparse d0;                 ///< edges × vertices: (d0ψ)_ab = ψ_b − ψ_a
    Sparse d1;                 ///< triangles × edges: ±1 as each side runs along its edge
    Eigen::VectorXd star0;     ///< barycentric vertex areas
    Eigen::VectorXd star1;     ///< cotan weights (may be negative, see above)
    Eigen::VectorXd star2;     ///< 1 / triangle area
    Eigen::VectorXd area;      ///< triangle areas
    std::vector<Vec3> normal;  ///< unit normal of each triangle (counter-clockwise: outward)

    /// The Laplace–Beltrami stiffness d0ᵀ⋆1d0 (mass: ⋆0).
    Sparse laplacian() const;
    double totalArea() const { return area.sum(); }
};

/// The DEC of a checked surface.
SurfaceDec buildSurfaceDec(const TriangleMesh& mesh, SurfaceTopology topology);

/// Vorticity at the vertices of each column of `fluxes` (ω = −⋆0⁻¹d0ᵀ⋆1 F).
Eigen::MatrixXd vertexVorticity(const SurfaceDec& dec, const Eigen::MatrixXd& fluxes);

/// The constant velocity in each triangle as a linear map of the edge fluxes, in the triangle's
/// own orthonormal frame (e1 along its first side, e2 = n × e1): the Whitney reconstruction
/// u = n × (1/3)Σ F_ab (∇φ_b − ∇φ_a) over the sides a→b, exact for fluxes with d1 F = 0 (which
/// are d0 of a linear function on each triangle). One row per triangle in each component.
struct FaceVelocityMap {
    SurfaceDec::Sparse alongE1, alongE2;  ///< triangles × edges
    std::vector<Vec3> e1, e2;
};
FaceVelocityMap faceVelocityMap(const SurfaceDec& dec, const TriangleMesh& mesh);

}  // namespace modeflow
