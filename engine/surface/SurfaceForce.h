#pragma once
/// @file SurfaceForce.h
/// Stirring on a surface (`modeflow stir`): Gaussian splats of force density (ForceSplat.h, the
/// grid's stirring splats), each vertex's share turned into the vertex's tangent plane, projected
/// on the velocity basis as f_k = ∫ g·u_k dA ≈ Σ_v ⋆0_v g(x_v)·u_k(x_v), u_k the mode's velocity
/// at the vertices (BasisCache::Surface::vertexVelocity). As on a grid, the power the force puts
/// in is v·f = ∫ g·u dA. The CPU reference of device::SurfaceForce.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "engine/simulation/ForceSplat.h"

namespace modeflow {

class SurfaceForce {
public:
    /// Keeps a reference to `cache`, which must outlive it.
    /// @throw modeflow::Error when the cache is not a surface basis.
    explicit SurfaceForce(const BasisCache& cache);

    /// The modal force of `splats` (zero for none).
    /// @throw modeflow::Error for more than maxForceSplats splats or a radius that is not
    ///        positive.
    Eigen::VectorXd project(std::span<const ForceSplat> splats) const;

private:
    const BasisCache& mCache;
    std::vector<Vec3> mNormals;  ///< VertexNormals.h
};

}  // namespace modeflow
