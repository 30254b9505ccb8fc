#pragma once
/// @file MeshRayHit.h
/// Where a ray first meets a triangle mesh (Möller–Trumbore against every triangle): what the
/// stir pointer touches on a surface.

#include <optional>

#include "engine/core/TriangleMesh.h"

namespace modeflow::stir {

struct MeshHit {
    Vec3 point{};
    int triangle = -1;
    double distance = 0.0;  ///< along the ray, in lengths of `direction`
};

/// The nearest point where origin + t·direction (t > 0) meets a triangle of `mesh`, from either
/// side; nullopt when the ray misses the mesh.
std::optional<MeshHit> nearestHit(const TriangleMesh& mesh, const Vec3& origin,
                                  const Vec3& direction);

}  // namespace modeflow::stir
