/// @file MeshRayHit.cpp

#include "engine/stir/MeshRayHit.h"

#include <cmath>

#include "engine/core/Vec3Math.h"

namespace modeflow::stir {

std::optional<MeshHit> nearestHit(const TriangleMesh& mesh, const Vec3& origin,
                                  const Vec3& direction) {
    std::optional<MeshHit> nearest;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3& a = mesh.vertices[std::size_t(mesh.triangles[t][0])];
        const Vec3 e1 = sub(mesh.vertices[std::size_t(mesh.triangles[t][1])], a);
        const Vec3 e2 = sub(mesh.vertices[std::size_t(mesh.triangles[t][2])], a);
        const Vec3 p = cross(direction, e2);
        const double det = dot(e1, p);
        if (std::abs(det) < 1e-300) continue;  // the ray runs in the triangle's plane
        const Vec3 s = sub(origin, a);
        const double u = dot(s, p) / det;
        if (u < 0.0 || u > 1.0) continue;
        const Vec3 q = cross(s, e1);
        const double v = dot(direction, q) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const double distance = dot(e2, q) / det;
        if (!(distance > 0.0) || (nearest && distance >= nearest->distance)) continue;
        MeshHit hit;
        for (int k = 0; k < 3; ++k) hit.point[k] = origin[k] + distance * direction[k];
        hit.triangle = int(t);
        hit.distance = distance;
        nearest = hit;
    }
    return nearest;
}

}  // namespace modeflow::stir
