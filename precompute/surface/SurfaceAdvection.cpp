/// @file SurfaceAdvection.cpp

#include "precompute/surface/SurfaceAdvection.h"

#include <Eigen/Geometry>

#include "engine/core/PackedLayout.h"

namespace modeflow {
namespace {

using Triplet = Eigen::Triplet<double>;

Eigen::Vector3d point(const TriangleMesh& mesh, int v) {
    const Vec3& p = mesh.vertices[std::size_t(v)];
    return {p[0], p[1], p[2]};
}

Eigen::Vector3d vec(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

Eigen::MatrixXd surfaceAdvection(const SurfaceDec& dec, const TriangleMesh& mesh,
                                 const Eigen::MatrixXd& scalarModes,
                                 const Eigen::MatrixXd& velocityModes) {
    const FaceVelocityMap map = faceVelocityMap(dec, mesh);
    const auto triangles = Eigen::Index(mesh.triangles.size());
    const Eigen::Index vertices = dec.star0.size();
    // Per triangle: A_t/3 at each corner (A_t · mean), and ∇φ_k along e1 and e2.
    std::vector<Triplet> mean, along1, along2;
    for (Eigen::Index t = 0; t < triangles; ++t) {
        const auto& tri = mesh.triangles[std::size_t(t)];
        const Eigen::Vector3d p[3] = {point(mesh, tri[0]), point(mesh, tri[1]),
                                      point(mesh, tri[2])};
        const Eigen::Vector3d n = vec(dec.normal[std::size_t(t)]);
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d g =
                n.cross(p[(k + 2) % 3] - p[(k + 1) % 3]) / (2.0 * dec.area[t]);
            mean.emplace_back(t, tri[std::size_t(k)], dec.area[t] / 3.0);
            along1.emplace_back(t, tri[std::size_t(k)], g.dot(vec(map.e1[std::size_t(t)])));
            along2.emplace_back(t, tri[std::size_t(k)], g.dot(vec(map.e2[std::size_t(t)])));
        }
    }
    SurfaceDec::Sparse meanMap(triangles, vertices), g1Map(triangles, vertices),
        g2Map(triangles, vertices);
    meanMap.setFromTriplets(mean.begin(), mean.end());
    g1Map.setFromTriplets(along1.begin(), along1.end());
    g2Map.setFromTriplets(along2.begin(), along2.end());
    const Eigen::MatrixXd weighted = meanMap * scalarModes;
    const Eigen::MatrixXd g1 = g1Map * scalarModes, g2 = g2Map * scalarModes;
    const Eigen::MatrixXd u1 = map.alongE1 * velocityModes, u2 = map.alongE2 * velocityModes;

    const auto m = std::size_t(scalarModes.cols());
    Eigen::MatrixXd packed(Eigen::Index(pairCount(m)), velocityModes.cols());
    for (Eigen::Index mode = 0; mode < velocityModes.cols(); ++mode) {
        const Eigen::MatrixXd grad =
            u1.col(mode).asDiagonal() * g1 + u2.col(mode).asDiagonal() * g2;
        const Eigen::MatrixXd a = weighted.transpose() * grad;
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t j = i + 1; j < m; ++j)
                packed(Eigen::Index(pairIndex(m, i, j)), mode) =
                    0.5 *
                    (a(Eigen::Index(i), Eigen::Index(j)) - a(Eigen::Index(j), Eigen::Index(i)));
    }
    return packed;
}

Eigen::MatrixXd surfaceVertexVelocity(const SurfaceDec& dec, const TriangleMesh& mesh,
                                      const Eigen::MatrixXd& velocityModes) {
    const FaceVelocityMap map = faceVelocityMap(dec, mesh);
    const Eigen::MatrixXd u1 = map.alongE1 * velocityModes, u2 = map.alongE2 * velocityModes;
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(3 * dec.star0.size(), velocityModes.cols());
    Eigen::VectorXd weight = Eigen::VectorXd::Zero(dec.star0.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const double a = dec.area[Eigen::Index(t)];
        for (int v : mesh.triangles[t]) {
            weight[v] += a;
            for (int k = 0; k < 3; ++k)
                out.row(3 * v + k) += a * (u1.row(Eigen::Index(t)) * map.e1[t][std::size_t(k)] +
                                           u2.row(Eigen::Index(t)) * map.e2[t][std::size_t(k)]);
        }
    }
    for (Eigen::Index v = 0; v < weight.size(); ++v) out.middleRows(3 * v, 3) /= weight[v];
    return out;
}

}  // namespace modeflow
