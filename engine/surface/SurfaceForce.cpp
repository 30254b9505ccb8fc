/// @file SurfaceForce.cpp

#include "engine/surface/SurfaceForce.h"

#include <cmath>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/VertexNormals.h"

namespace modeflow {

SurfaceForce::SurfaceForce(const BasisCache& cache) : mCache(cache) {
    if (cache.kind != BasisKind::Surface)
        throw Error("surface force: the basis is not a surface's");
    mNormals = vertexNormals(cache.surface.mesh);
}

Eigen::VectorXd SurfaceForce::project(std::span<const ForceSplat> splats) const {
    const Eigen::MatrixXd& u = mCache.surface.vertexVelocity;
    if (splats.empty()) return Eigen::VectorXd::Zero(u.cols());
    if (splats.size() > maxForceSplats)
        throw Error("surface force: " + std::to_string(splats.size()) + " splats, room for " +
                    std::to_string(maxForceSplats));
    for (const ForceSplat& splat : splats)
        if (!(splat.radius > 0.0))
            throw Error("surface force: a splat radius must be positive, got " +
                        std::to_string(splat.radius));
    const std::vector<Vec3>& x = mCache.surface.mesh.vertices;
    const Eigen::VectorXd& star0 = mCache.scalar.cellStar;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(u.rows());  // ⋆0 g per vertex, x, y, z
    for (std::size_t v = 0; v < x.size(); ++v) {
        Vec3 force{};
        for (const ForceSplat& splat : splats) {
            double r2 = 0.0;
            for (int k = 0; k < 3; ++k)
                r2 += (x[v][k] - splat.centre[k]) * (x[v][k] - splat.centre[k]);
            const double weight = std::exp(-r2 / (splat.radius * splat.radius));
            for (int k = 0; k < 3; ++k) force[k] += weight * splat.force[k];
        }
        const Vec3& n = mNormals[v];
        const double normal = force[0] * n[0] + force[1] * n[1] + force[2] * n[2];
        for (int k = 0; k < 3; ++k)
            g[Eigen::Index(3 * v) + k] = star0[Eigen::Index(v)] * (force[k] - normal * n[k]);
    }
    return u.transpose() * g;
}

}  // namespace modeflow
