#pragma once
/// @file TestBases.h
/// Velocity bases for the reconstruction and force projection tests: random ⋆-orthonormal modes
/// on a box grid (any size, fast, not divergence-free), and real cut-cell bases computed by the
/// precompute library (divergence-free, free-slip, realistic boundaries).

#include <random>

#include <Eigen/QR>

#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "engine/format/BasisCache.h"
#include "precompute/Precompute.h"
#include "engine/core/SceneSpec.h"

namespace modeflow::testing {

/// A vector of standard normal values.
inline Eigen::VectorXd normalVector(Eigen::Index n, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    Eigen::VectorXd v(n);
    for (double& x : v) x = normal(random);
    return v;
}

/// A grid over a non-cubic box, so axis mix-ups show.
inline GridSpec boxGrid(int dim, int cells) {
    GridSpec grid;
    grid.dim = dim;
    grid.resolution = {cells, cells, dim == 3 ? cells : 1};
    grid.boundsMin = {-1.0, -0.9, dim == 3 ? -0.8 : 0.0};
    grid.boundsMax = {1.2, 1.0, dim == 3 ? 1.3 : 1.0};
    return grid;
}

/// `modes` random modes on every face not on the box, with random cut fractions in [0.3, 1]
/// (⋆ = h / (area × fraction), as for a cut face), ⋆-orthonormalized.
inline BasisCache syntheticBasis(const GridSpec& grid, int modes, unsigned seed) {
    BasisCache cache;
    cache.grid = grid;
    const MacGrid mac = MacGrid::fromSpec(grid);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> fraction(0.3, 1.0);
    std::vector<double> star;
    for (std::int64_t f = 0; f < mac.faceTotal(); ++f) {
        const FaceLocation face = locateFace(mac, f);
        if (face.pos[face.axis] == 0 || face.pos[face.axis] == mac.cells[face.axis]) continue;  // box wall
        cache.faces.push_back(f);
        star.push_back(mac.spacing[face.axis] / (mac.faceArea(face.axis) * fraction(random)));
    }
    cache.faceStar = Eigen::Map<const Eigen::VectorXd>(star.data(), Eigen::Index(star.size()));
    const Eigen::Index dofs = cache.faceStar.size();
    std::normal_distribution<double> normal;
    Eigen::MatrixXd x(dofs, modes);
    for (Eigen::Index j = 0; j < x.cols(); ++j)
        for (Eigen::Index i = 0; i < x.rows(); ++i) x(i, j) = normal(random);
    // Orthonormal Q for the plain inner product of S x, S = diag(√⋆); Ψ = S⁻¹ Q is ⋆-orthonormal.
    const Eigen::VectorXd root = cache.faceStar.cwiseSqrt();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(root.asDiagonal() * x);
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(dofs, modes);
    cache.velocity.modes = root.cwiseInverse().asDiagonal() * q;
    cache.velocity.eigenvalues = Eigen::VectorXd::LinSpaced(modes, 1.0, double(modes));
    return cache;
}

/// A real basis: a disk of radius 1 in [-1.1, 1.1]² (2D) or a ball of radius 1 in [-1.1, 1.1]³,
/// free-slip, cut cells.
inline BasisCache realBasis(int dim, int cells, int modes) {
    SceneSpec scene;
    scene.name = "test";
    scene.grid.dim = dim;
    scene.grid.resolution = {cells, cells, dim == 3 ? cells : 1};
    scene.grid.boundsMin = {-1.1, -1.1, dim == 3 ? -1.1 : 0.0};
    scene.grid.boundsMax = {1.1, 1.1, dim == 3 ? 1.1 : 0.0};
    ShapeSpec ball;
    ball.kind = ShapeKind::Ball;
    ball.center = {0.0, 0.0, 0.0};
    ball.radius = 1.0;
    scene.domain = {ball};
    scene.basis.velocityModes = {{1, modes}};
    scene.basis.scalarModes = 0;
    Progress quiet = Progress::silent();
    return computeBasis(scene, quiet);
}

/// The real bases the tests share, computed once per executable.
inline const BasisCache& disk2d() {
    static const BasisCache cache = realBasis(2, 32, 20);
    return cache;
}
inline const BasisCache& ball3d() {
    static const BasisCache cache = realBasis(3, 12, 10);
    return cache;
}

}  // namespace modeflow::testing
