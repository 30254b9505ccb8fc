#include "precompute/BasisChecks.h"

#include "precompute/dec/CubicalComplex.h"

namespace modeflow {
namespace {

double orthonormalityError(const Eigen::MatrixXd& modes, const Eigen::VectorXd& mass) {
    if (modes.cols() == 0) return 0.0;
    const Eigen::MatrixXd gram = modes.transpose() * mass.asDiagonal() * modes;
    return (gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff();
}

}  // namespace

BasisChecks checkBasis(const BasisCache& cache) {
    BasisChecks checks;
    checks.velocityOrthonormality = orthonormalityError(cache.velocity.modes, cache.faceStar);
    checks.scalarOrthonormality = orthonormalityError(cache.scalar.modes, cache.scalar.cellStar);

    // Divergence through the full incidence matrix: a flux leaking through a non-DOF face would
    // show up in the cells beside it.
    const CubicalComplex complex(cache.grid);
    const SparseMatrix d = complex.incidence(cache.grid.dim - 1);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(complex.count(cache.grid.dim - 1));
    for (Eigen::Index m = 0; m < cache.velocity.modes.cols(); ++m) {
        for (size_t i = 0; i < cache.faces.size(); ++i)
            full[cache.faces[i]] = cache.velocity.modes(Eigen::Index(i), m);
        const double size = full.cwiseAbs().maxCoeff();
        const Eigen::VectorXd div = d * full;
        if (size > 0.0)
            checks.maxDivergence = std::max(checks.maxDivergence, div.cwiseAbs().maxCoeff() / size);
    }
    return checks;
}

}  // namespace modeflow
