/// @file SurfaceCoefficients.cpp

#include "precompute/surface/SurfaceCoefficients.h"

#include "engine/core/PackedLayout.h"
#include "precompute/coefficients/CoefficientAssembly.h"

namespace modeflow {

std::vector<double> assembleSurfaceCoefficients(const SurfaceDec& dec, const TriangleMesh& mesh,
                                                const Eigen::MatrixXd& modes) {
    std::vector<double> packed(packedSize(std::size_t(modes.cols())), 0.0);
    if (modes.cols() < 2) return packed;
    std::vector<Eigen::Triplet<double>> corners;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int v : mesh.triangles[t])
            corners.emplace_back(Eigen::Index(t), v, dec.area[Eigen::Index(t)] / 3.0);
    SurfaceDec::Sparse cornerWeights(Eigen::Index(mesh.triangles.size()), dec.star0.size());
    cornerWeights.setFromTriplets(corners.begin(), corners.end());
    const Eigen::MatrixXd omega = cornerWeights * vertexVorticity(dec, modes);
    const FaceVelocityMap velocity = faceVelocityMap(dec, mesh);
    accumulateCrossProducts(omega, velocity.alongE1 * modes, velocity.alongE2 * modes, packed);
    return packed;
}

}  // namespace modeflow
