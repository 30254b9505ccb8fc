#include "precompute/solve/WindBaseFlows.h"

#include <algorithm>
#include <optional>
#include <string>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "engine/core/Error.h"
#include "precompute/dec/FluidComponents.h"
#include "precompute/solve/Laplacians.h"

namespace modeflow {
namespace {

using ColMatrix = Eigen::SparseMatrix<double>;

/// |face ∩ Ω| of the face DOF `dof`: its dual edge over its ⋆.
double fluidArea(const CubicalComplex& cx, const CutCellDec& dec, std::int64_t dof) {
    const Element f = cx.element(cx.dim() - 1, dec.faces.toGlobal[std::size_t(dof)]);
    return dualMeasure(cx.grid(), f) / dec.faceStar[dof];
}

/// The normal axis of a face (its one missing axis).
int normalOf(const Element& face, int dim) {
    for (int a = 0; a < dim; ++a)
        if (!((face.axes >> a) & 1u)) return a;
    return dim - 1;
}

/// One face on a side of the box the wind crosses, and the cell DOF inside it.
struct SideFace {
    std::int64_t face, cell;
    double area, dual;  ///< |face ∩ Ω| and its dual edge (half a cell)
    bool inflow;        ///< the upstream side
};

/// The faces of the box's two sides along `a` with fluid, for a wind along `direction` · e_a.
std::vector<SideFace> sideFaces(const CubicalComplex& cx, const CutCellMeasures& measures,
                                const CutCellDec& dec, int a, int direction) {
    const GridSpec& grid = cx.grid();
    std::vector<SideFace> sides;
    cx.forEachSideFace(a, [&](const Element& face, const Element& cell) {
        const std::int64_t g = cx.index(face);
        const double area = primalMeasure(grid, face.axes) * measures.sideFraction[std::size_t(g)];
        const std::int64_t c = dec.cells.toLocal[std::size_t(cx.index(cell))];
        if (area <= 0.0 || c < 0) return;
        sides.push_back(
            {g, c, area, dualMeasure(grid, face), (face.pos[a] == 0) == (direction > 0)});
    });
    return sides;
}

}  // namespace

std::vector<std::vector<double>> windBaseFlows(const CubicalComplex& cx,
                                               const CutCellMeasures& measures,
                                               const CutCellDec& dec) {
    const GridSpec& grid = cx.grid();
    const int n = grid.dim;
    const ColMatrix d(dec.div);  // outward fluxes of the cells
    const Eigen::VectorXd conductance = dec.faceStar.cwiseInverse();
    const ColMatrix poisson = d * conductance.asDiagonal() * d.transpose();
    const Eigen::Index cells = d.rows(), faces = d.cols();
    const FluidComponents parts = fluidComponents(dec);

    std::vector<std::vector<double>> flows;
    for (int a = 0; a < n; ++a)
        for (const int direction : {1, -1}) {
            if (direction < 0 && grid.isPeriodic(a)) {  // no sides: the flow is linear in U
                std::vector<double> reversed = flows.back();
                for (double& u : reversed) u = -u;
                flows.push_back(std::move(reversed));
                continue;
            }
            // The unit wind's fluxes through the face DOFs, and what its divergence asks of φ:
            // (d ⋆⁻¹ dᵀ) φ = d F(wind) + what the sides let out.
            Eigen::VectorXd wind = Eigen::VectorXd::Zero(faces);
            for (Eigen::Index f = 0; f < faces; ++f)
                if (normalOf(cx.element(n - 1, dec.faces.toGlobal[std::size_t(f)]), n) == a)
                    wind[f] = direction * fluidArea(cx, dec, f);
            Eigen::VectorXd rhs = d * wind;
            // Upstream the air comes in at the wind's speed; downstream it leaves at
            // 1 − φ/dual along the wind (φ = 0 on the side, half a cell from the cell inside).
            Eigen::VectorXd sideConductance = Eigen::VectorXd::Zero(cells);
            const std::vector<SideFace> sides = sideFaces(cx, measures, dec, a, direction);
            // By component: whether the air may leave it (a downstream side, an open side).
            std::vector<bool> drained = parts.open;
            for (const SideFace& s : sides) {
                rhs[s.cell] += s.inflow ? -s.area : s.area;
                if (!s.inflow) {
                    sideConductance[s.cell] += s.area / s.dual;
                    drained[std::size_t(parts.of[std::size_t(s.cell)])] = true;
                }
            }
            // Air that enters a part of the fluid with no downstream side has no way out.
            std::vector<double> net(std::size_t(cells), 0.0);
            for (Eigen::Index c = 0; c < cells; ++c)
                net[std::size_t(parts.of[std::size_t(c)])] += rhs[c];
            bool blocked = false;
            for (Eigen::Index c = 0; c < cells; ++c)
                blocked |=
                    !drained[std::size_t(c)] && parts.of[std::size_t(c)] == c &&
                    std::abs(net[std::size_t(c)]) > 1e-9 * primalMeasure(grid, (1u << n) - 1);
            if (blocked) {
                flows.emplace_back();
                continue;
            }
            ColMatrix system = poisson;
            system += ColMatrix(sideConductance.asDiagonal());
            // A component no downstream side reaches (a periodic axis, a pocket) has φ up to a
            // constant, which its consistent right-hand side does not see; a tiny shift keeps the
            // solver definite.
            const double shift = 1e-13 * system.diagonal().cwiseAbs().maxCoeff();
            for (Eigen::Index i = 0; i < cells; ++i) system.coeffRef(i, i) += shift;
            Eigen::ConjugateGradient<ColMatrix, Eigen::Lower | Eigen::Upper,
                                     Eigen::IncompleteCholesky<double>>
                solver;
            solver.setTolerance(1e-13);
            solver.setMaxIterations(int(std::min<Eigen::Index>(20 * cells + 100, 1 << 30)));
            solver.compute(system);
            const Eigen::VectorXd phi = solver.solve(rhs);
            if (solver.info() != Eigen::Success)
                throw Error("wind base flow along axis " + std::to_string(a) +
                            ": the Poisson solve over " + std::to_string(cells) +
                            " cells did not converge (residual " + std::to_string(solver.error()) +
                            ")");
            const Eigen::VectorXd fluxes = wind - conductance.cwiseProduct(d.transpose() * phi);
            std::vector<double> flow(std::size_t(cx.count(n - 1)), 0.0);
            for (Eigen::Index f = 0; f < faces; ++f)
                flow[std::size_t(dec.faces.toGlobal[std::size_t(f)])] =
                    fluxes[f] / fluidArea(cx, dec, f);
            for (const SideFace& s : sides)
                flow[std::size_t(s.face)] =
                    direction * (s.inflow ? 1.0 : 1.0 - phi[s.cell] / s.dual);
            flows.push_back(std::move(flow));
        }
    return flows;
}

namespace {

/// Per periodic axis a column: each mode's net flux through the cross-section at the seam (the
/// same through every cross-section: the modes are divergence-free).
Eigen::MatrixXd periodicFluxes(const CubicalComplex& cx, const CutCellDec& dec,
                               const Eigen::MatrixXd& modes) {
    const int n = cx.dim();
    std::vector<Eigen::VectorXd> columns;
    for (int a = 0; a < n; ++a) {
        if (!cx.grid().isPeriodic(a)) continue;
        Eigen::VectorXd section = Eigen::VectorXd::Zero(modes.rows());
        for (Eigen::Index f = 0; f < section.size(); ++f) {
            const Element face = cx.element(n - 1, dec.faces.toGlobal[std::size_t(f)]);
            if (normalOf(face, n) == a && face.pos[a] == 0) section[f] = 1.0;
        }
        columns.push_back(modes.transpose() * section);
    }
    Eigen::MatrixXd q(modes.cols(), Eigen::Index(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) q.col(Eigen::Index(c)) = columns[c];
    return q;
}

}  // namespace

std::vector<std::vector<double>> windStokesCorrections(
    const CubicalComplex& cx, const CutCellDec& dec, const Eigen::MatrixXd& modes,
    const Eigen::VectorXd& eigenvalues, const std::vector<std::vector<double>>& flows) {
    const ColMatrix curlCurl = velocityCurlCurl(dec);
    // Λ⁻¹ on the modes with Λ > 0 (a harmonic mode's c is 0), and the fluxes a correction must
    // not change: along a periodic axis the held flow's flux is the wind's, kept as a pressure
    // drop keeps a channel's (Stokes with no-slip walls and no drop is rest).
    Eigen::VectorXd inverse = Eigen::VectorXd::Zero(eigenvalues.size());
    for (Eigen::Index k = 0; k < eigenvalues.size(); ++k)
        if (eigenvalues[k] > 0.0) inverse[k] = 1.0 / eigenvalues[k];
    const Eigen::MatrixXd q = periodicFluxes(cx, dec, modes);
    std::optional<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>> held;
    if (q.cols() > 0) held.emplace(q.transpose() * inverse.asDiagonal() * q);
    std::vector<std::vector<double>> corrections;
    for (const std::vector<double>& flow : flows) {
        if (flow.empty()) {
            corrections.emplace_back();
            continue;
        }
        Eigen::VectorXd fluxes(modes.rows());
        for (Eigen::Index f = 0; f < fluxes.size(); ++f)
            fluxes[f] =
                flow[std::size_t(dec.faces.toGlobal[std::size_t(f)])] * fluidArea(cx, dec, f);
        // c = −Λ⁻¹(Ψᵀ K B + Q μ) with Qᵀ c = 0.
        Eigen::VectorXd drive = modes.transpose() * (curlCurl * fluxes);
        if (held) drive -= q * held->solve(q.transpose() * inverse.cwiseProduct(drive));
        const Eigen::VectorXd c = -inverse.cwiseProduct(drive);
        corrections.emplace_back(c.data(), c.data() + c.size());
    }
    return corrections;
}

}  // namespace modeflow
