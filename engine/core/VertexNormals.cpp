#include "engine/core/VertexNormals.h"

#include <cmath>

namespace modeflow {

std::vector<Vec3> vertexNormals(const TriangleMesh& mesh) {
    std::vector<Vec3> normals(mesh.vertices.size(), Vec3{});
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[std::size_t(t[0])], &b = mesh.vertices[std::size_t(t[1])],
                   &c = mesh.vertices[std::size_t(t[2])];
        const Vec3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const Vec3 ac{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        // Twice the triangle's area times its normal: counter-clockwise seen from outside.
        const Vec3 n{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                     ab[0] * ac[1] - ab[1] * ac[0]};
        for (const int v : t)
            for (int k = 0; k < 3; ++k) normals[std::size_t(v)][k] += n[k];
    }
    for (Vec3& n : normals) {
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length > 0.0)
            for (double& x : n) x /= length;
    }
    return normals;
}

}  // namespace modeflow
