#include "precompute/BasisChecks.h"

#include "engine/core/Error.h"
#include "precompute/dec/CubicalComplex.h"
#include "precompute/surface/SurfaceDec.h"

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
    if (cache.kind == BasisKind::Surface) {
        // The net flux into every triangle, through d1 rebuilt from the stored mesh.
        const SurfaceTopology topology = checkClosedSurface(cache.surface.mesh, "cached surface");
        if (topology.edges != cache.surface.edges)
            throw Error("the cached surface's edges do not match its triangles; rerun precompute with --force");
        const SurfaceDec dec = buildSurfaceDec(cache.surface.mesh, topology);
        for (Eigen::Index m = 0; m < cache.velocity.modes.cols(); ++m) {
            const double size = cache.velocity.modes.col(m).cwiseAbs().maxCoeff();
            if (size > 0.0)
                checks.maxDivergence = std::max(
                    checks.maxDivergence, (dec.d1 * cache.velocity.modes.col(m)).cwiseAbs().maxCoeff() / size);
        }
        return checks;
    }

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
