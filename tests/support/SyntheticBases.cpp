#include "tests/support/SyntheticBases.h"

#include <random>
#include <vector>

#include <Eigen/Cholesky>

#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "tests/support/RandomCoefficients.h"

namespace modeflow::testing {

GridSpec boxGrid(int dim, int cells) {
    GridSpec grid;
    grid.dim = dim;
    grid.resolution = {cells, cells, dim == 3 ? cells : 1};
    grid.boundsMin = {-1.0, -0.9, dim == 3 ? -0.8 : 0.0};
    grid.boundsMax = {1.2, 1.0, dim == 3 ? 1.3 : 1.0};
    return grid;
}

BasisCache syntheticBasis(const GridSpec& grid, int modes, unsigned seed) {
    BasisCache cache = syntheticModes(grid, modes, seed);
    cache.coefficients.storage = BasisCache::Coefficients::Storage::Dense;
    cache.coefficients.packed = randomDense(modes, seed).packed();
    cache.coefficients.density = 1.0;
    return cache;
}

BasisCache syntheticModes(const GridSpec& grid, int modes, unsigned seed) {
    BasisCache cache;
    cache.grid = grid;
    const MacGrid mac = MacGrid::fromSpec(grid);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> fraction(0.3, 1.0);
    std::vector<double> star;
    for (std::int64_t f = 0; f < mac.faceTotal(); ++f) {
        const FaceLocation face = locateFace(mac, f);
        if (mac.isWallFace(face.axis, face.pos[face.axis])) continue;
        cache.faces.push_back(f);
        star.push_back(mac.spacing[face.axis] / (mac.faceArea(face.axis) * fraction(random)));
    }
    cache.faceStar = Eigen::Map<const Eigen::VectorXd>(star.data(), Eigen::Index(star.size()));
    cache.cellFraction.assign(std::size_t(mac.cellCount()), 1.0);

    // Ψ = X R⁻¹ with RᵀR = Xᵀ⋆X (Cholesky QR, in place: a 64³ basis of 200 modes is 1.2 GB):
    // Y = S X, S = diag(√⋆), has orthonormal columns Y R⁻¹, so Ψ = S⁻¹ Y R⁻¹ is ⋆-orthonormal.
    // Random normal columns are well conditioned, so one pass is exact to round-off.
    std::normal_distribution<double> normal;
    Eigen::MatrixXd& x = cache.velocity.modes;
    x.resize(cache.faceStar.size(), modes);
    for (Eigen::Index j = 0; j < x.cols(); ++j)
        for (Eigen::Index i = 0; i < x.rows(); ++i) x(i, j) = normal(random);
    const Eigen::VectorXd root = cache.faceStar.cwiseSqrt();
    x.array().colwise() *= root.array();
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(modes, modes);
    gram.selfadjointView<Eigen::Lower>().rankUpdate(x.transpose());
    const Eigen::LLT<Eigen::MatrixXd> cholesky(gram.selfadjointView<Eigen::Lower>());
    cholesky.matrixU().solveInPlace<Eigen::OnTheRight>(x);
    x.array().colwise() /= root.array();
    cache.velocity.eigenvalues = Eigen::VectorXd::LinSpaced(modes, 1.0, double(modes));
    cache.coefficients.storage = BasisCache::Coefficients::Storage::None;
    return cache;
}

}  // namespace modeflow::testing
