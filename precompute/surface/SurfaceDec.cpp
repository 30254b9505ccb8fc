/// @file SurfaceDec.cpp

#include "precompute/surface/SurfaceDec.h"

#include <cmath>

#include <Eigen/Geometry>

namespace modeflow {
namespace {

using Triplet = Eigen::Triplet<double>;

Eigen::Vector3d point(const TriangleMesh& mesh, int v) {
    const Vec3& p = mesh.vertices[std::size_t(v)];
    return {p[0], p[1], p[2]};
}

}  // namespace

SurfaceDec::Sparse SurfaceDec::laplacian() const {
    Sparse l = d0.transpose() * star1.asDiagonal() * d0;
    l.makeCompressed();
    return l;
}

SurfaceDec buildSurfaceDec(const TriangleMesh& mesh, SurfaceTopology topology) {
    SurfaceDec dec;
    dec.topology = std::move(topology);
    const auto& top = dec.topology;
    const Eigen::Index vertices = Eigen::Index(mesh.vertices.size());
    const Eigen::Index edges = Eigen::Index(top.edges.size());
    const Eigen::Index triangles = Eigen::Index(mesh.triangles.size());

    std::vector<Triplet> d0, d1;
    for (Eigen::Index e = 0; e < edges; ++e) {
        d0.emplace_back(e, top.edges[std::size_t(e)][0], -1.0);
        d0.emplace_back(e, top.edges[std::size_t(e)][1], 1.0);
    }
    dec.star0 = Eigen::VectorXd::Zero(vertices);
    dec.star1 = Eigen::VectorXd::Zero(edges);
    dec.area.resize(triangles);
    dec.normal.resize(std::size_t(triangles));
    for (Eigen::Index t = 0; t < triangles; ++t) {
        const auto& tri = mesh.triangles[std::size_t(t)];
        const Eigen::Vector3d p[3] = {point(mesh, tri[0]), point(mesh, tri[1]),
                                      point(mesh, tri[2])};
        const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
        const double a = 0.5 * n.norm();
        dec.area[t] = a;
        const Eigen::Vector3d unit = n.normalized();
        dec.normal[std::size_t(t)] = {unit[0], unit[1], unit[2]};
        for (int k = 0; k < 3; ++k) {
            const int e = top.triangleEdges[std::size_t(t)][std::size_t(k)];
            d1.emplace_back(t, e, double(top.triangleEdgeSigns[std::size_t(t)][std::size_t(k)]));
            // Side k runs from corner k to k+1; the angle facing it is at corner k+2.
            const Eigen::Vector3d u = p[k] - p[(k + 2) % 3], w = p[(k + 1) % 3] - p[(k + 2) % 3];
            dec.star1[e] += 0.5 * u.dot(w) / u.cross(w).norm();
            dec.star0[tri[std::size_t(k)]] += a / 3.0;
        }
    }
    dec.star2 = dec.area.cwiseInverse();
    dec.d0.resize(edges, vertices);
    dec.d0.setFromTriplets(d0.begin(), d0.end());
    dec.d1.resize(triangles, edges);
    dec.d1.setFromTriplets(d1.begin(), d1.end());
    return dec;
}

Eigen::MatrixXd vertexVorticity(const SurfaceDec& dec, const Eigen::MatrixXd& fluxes) {
    return -(dec.star0.cwiseInverse().asDiagonal() *
             (dec.d0.transpose() * (dec.star1.asDiagonal() * fluxes)));
}

FaceVelocityMap faceVelocityMap(const SurfaceDec& dec, const TriangleMesh& mesh) {
    const auto& top = dec.topology;
    const Eigen::Index triangles = Eigen::Index(mesh.triangles.size());
    FaceVelocityMap map;
    map.e1.resize(std::size_t(triangles));
    map.e2.resize(std::size_t(triangles));
    std::vector<Triplet> along1, along2;
    for (Eigen::Index t = 0; t < triangles; ++t) {
        const auto& tri = mesh.triangles[std::size_t(t)];
        const Eigen::Vector3d p[3] = {point(mesh, tri[0]), point(mesh, tri[1]),
                                      point(mesh, tri[2])};
        const Vec3& nv = dec.normal[std::size_t(t)];
        const Eigen::Vector3d n(nv[0], nv[1], nv[2]);
        const Eigen::Vector3d e1 = (p[1] - p[0]).normalized(), e2 = n.cross(e1);
        map.e1[std::size_t(t)] = {e1[0], e1[1], e1[2]};
        map.e2[std::size_t(t)] = {e2[0], e2[1], e2[2]};
        // ∇φ_k = n × (p_{k+2} − p_{k+1}) / 2A, and u = n × ∇ψ.
        Eigen::Vector3d gradient[3];
        for (int k = 0; k < 3; ++k)
            gradient[k] = n.cross(p[(k + 2) % 3] - p[(k + 1) % 3]) / (2.0 * dec.area[t]);
        for (int k = 0; k < 3; ++k) {
            // Side k from corner k to k+1: its flux F_{k→k+1} = sign · F_e.
            const int e = top.triangleEdges[std::size_t(t)][std::size_t(k)];
            const double sign = top.triangleEdgeSigns[std::size_t(t)][std::size_t(k)];
            const Eigen::Vector3d u = n.cross(gradient[(k + 1) % 3] - gradient[k]) * (sign / 3.0);
            along1.emplace_back(t, e, u.dot(e1));
            along2.emplace_back(t, e, u.dot(e2));
        }
    }
    map.alongE1.resize(triangles, Eigen::Index(top.edges.size()));
    map.alongE1.setFromTriplets(along1.begin(), along1.end());
    map.alongE2.resize(triangles, Eigen::Index(top.edges.size()));
    map.alongE2.setFromTriplets(along2.begin(), along2.end());
    return map;
}

}  // namespace modeflow
