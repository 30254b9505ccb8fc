#include "precompute/BasisChecks.h"

#include <algorithm>

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

/// The columns a check reads: the stored ones, or the sampled closed-form modes materialized.
template <typename Materialize>
Eigen::MatrixXd checkedColumns(const Eigen::MatrixXd& stored,
                               const std::vector<SeparableMode>& separable, std::int64_t dofs,
                               Materialize&& materialize, int& checked) {
    if (separable.empty() || stored.cols() == Eigen::Index(separable.size())) {
        checked = int(stored.cols());
        return stored;
    }
    std::vector<SeparableMode> picked;
    for (int m : checkedModes(dofs, int(separable.size())))
        picked.push_back(separable[std::size_t(m)]);
    checked = int(picked.size());
    return materialize(picked);
}

}  // namespace

std::vector<int> checkedModes(std::int64_t dofs, int count) {
    std::vector<int> out;
    if (double(dofs) * double(count) * double(count) <= kFullCheckWork) {
        for (int m = 0; m < count; ++m) out.push_back(m);
        return out;
    }
    constexpr int kPositions = 48;
    for (int p = 0; p < kPositions; ++p) {
        const int m = int(std::int64_t(p) * (count - 1) / (kPositions - 1));
        for (int q : {m, m + 1})
            if (q < count && (out.empty() || out.back() < q)) out.push_back(q);
    }
    return out;
}

BasisChecks checkBasis(const BasisCache& cache) {
    BasisChecks checks;
    const Eigen::MatrixXd velocity = checkedColumns(
        cache.velocity.modes, cache.velocity.separable, std::int64_t(cache.faces.size()),
        [&](const std::vector<SeparableMode>& m) {
            return velocityModeFluxes(cache.grid, cache.faces, m);
        },
        checks.velocityChecked);
    const Eigen::MatrixXd scalar = checkedColumns(
        cache.scalar.modes, cache.scalar.separable, std::int64_t(cache.scalar.cells.size()),
        [&](const std::vector<SeparableMode>& m) {
            return scalarModeValues(cache.grid, cache.scalar.cells, m);
        },
        checks.scalarChecked);
    checks.velocityOrthonormality = orthonormalityError(velocity, cache.faceStar);
    checks.scalarOrthonormality = orthonormalityError(scalar, cache.scalar.cellStar);
    if (cache.kind == BasisKind::Surface) {
        // The net flux into every triangle, through d1 rebuilt from the stored mesh.
        const SurfaceTopology topology = checkClosedSurface(cache.surface.mesh, "cached surface");
        if (topology.edges != cache.surface.edges)
            throw Error(
                "the cached surface's edges do not match its triangles; rerun precompute with "
                "--force");
        const SurfaceDec dec = buildSurfaceDec(cache.surface.mesh, topology);
        for (Eigen::Index m = 0; m < velocity.cols(); ++m) {
            const double size = velocity.col(m).cwiseAbs().maxCoeff();
            if (size > 0.0)
                checks.maxDivergence = std::max(
                    checks.maxDivergence, (dec.d1 * velocity.col(m)).cwiseAbs().maxCoeff() / size);
        }
        return checks;
    }

    // Divergence through the full incidence matrix: a flux leaking through a non-DOF face would
    // show up in the cells beside it.
    const CubicalComplex complex(cache.grid);
    const SparseMatrix d = complex.incidence(cache.grid.dim - 1);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(complex.count(cache.grid.dim - 1));
    for (Eigen::Index m = 0; m < velocity.cols(); ++m) {
        for (size_t i = 0; i < cache.faces.size(); ++i)
            full[cache.faces[i]] = velocity(Eigen::Index(i), m);
        const double size = full.cwiseAbs().maxCoeff();
        const Eigen::VectorXd div = d * full;
        if (size > 0.0)
            checks.maxDivergence = std::max(checks.maxDivergence, div.cwiseAbs().maxCoeff() / size);
    }
    return checks;
}

}  // namespace modeflow
