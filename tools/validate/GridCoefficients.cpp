#include "tools/validate/GridCoefficients.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/basis/VelocityBasis.h"
#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/reference/VelocityReconstruction.h"

namespace modeflow::validate {

FullTensorCoefficients::FullTensorCoefficients(int n, std::vector<double> full)
    : mN(n), mFull(std::move(full)) {
    if (mFull.size() != std::size_t(n) * n * n)
        throw Error("full coefficient tensor: " + std::to_string(mFull.size()) +
                    " entries for N = " + std::to_string(n));
}

void FullTensorCoefficients::apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                   Eigen::VectorXd& out) const {
    checkSize("apply", a);
    checkSize("apply", b);
    out.setZero(mN);
    for (int k = 0; k < mN; ++k) {
        const Eigen::Map<const Eigen::MatrixXd> ck(&mFull[std::size_t(k) * mN * mN], mN,
                                                   mN);  // (j, i)
        out[k] = a.dot(ck.transpose() * b);
    }
}

void FullTensorCoefficients::linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                                       Eigen::MatrixXd& byI, Eigen::MatrixXd& byJ) const {
    checkSize("linearize", a);
    checkSize("linearize", b);
    byI.setZero(mN, mN);
    byJ.setZero(mN, mN);
    for (int k = 0; k < mN; ++k) {
        const Eigen::Map<const Eigen::MatrixXd> ck(&mFull[std::size_t(k) * mN * mN], mN,
                                                   mN);  // ck(j, i)
        byI.row(k) = (ck * a).transpose();
        byJ.row(k) = (ck.transpose() * b).transpose();
    }
}

void FullTensorCoefficients::advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                                    Eigen::VectorXd& out) const {
    checkSize("advect", u);
    checkSize("advect", x);
    out.setZero(mN);
    for (int j = 0; j < mN; ++j) {
        const Eigen::Map<const Eigen::MatrixXd> cj(&mFull[std::size_t(j) * mN * mN], mN,
                                                   mN);  // cj(i, k)
        out += u[j] * (cj.transpose() * x);
    }
}

double FullTensorCoefficients::antisymmetryError() const {
    double worst = 0.0, largest = 0.0;
    for (int k = 0; k < mN; ++k)
        for (int i = 0; i < mN; ++i)
            for (int j = 0; j < mN; ++j) {
                worst = std::max(worst, std::abs(entry(k, i, j) + entry(j, i, k)));
                largest = std::max(largest, std::abs(entry(k, i, j)));
            }
    return largest > 0.0 ? worst / largest : 0.0;
}

namespace {

/// Cell-centred velocities of one mode: dim arrays over the grid's cells.
using CellField = std::vector<Eigen::VectorXd>;

CellField cellVelocity(const VelocityBasis& basis, const MacGrid& grid, int mode) {
    const std::vector<double> faces = reference::fluxesToFaceField(
        basis.cache(), basis.fluxes(Eigen::VectorXd::Unit(basis.modeCount(), mode)));
    const std::vector<Vec3> centred = reference::cellCentreVelocity(grid, faces);
    CellField field(std::size_t(grid.dim), Eigen::VectorXd(Eigen::Index(centred.size())));
    for (std::size_t c = 0; c < centred.size(); ++c)
        for (int a = 0; a < grid.dim; ++a) field[std::size_t(a)][Eigen::Index(c)] = centred[c][a];
    return field;
}

/// ∂_b of a cell field: central differences between fluid cells, one-sided where one neighbour
/// is outside Ω, 0 where both are.
Eigen::VectorXd derivative(const MacGrid& grid, const std::vector<double>& fraction,
                           const Eigen::VectorXd& f, int b) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(f.size());
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const std::array<int, 3> p{x, y, z};
                const std::int64_t c = grid.cellIndex(x, y, z);
                if (fraction[std::size_t(c)] <= 0.0) continue;
                std::array<int, 3> lo = p, hi = p;
                --lo[b], ++hi[b];
                const auto inside = [&](const std::array<int, 3>& q) {
                    return q[b] >= 0 && q[b] < grid.cells[b] &&
                           fraction[std::size_t(grid.cellIndex(q[0], q[1], q[2]))] > 0.0;
                };
                const bool hasLo = inside(lo), hasHi = inside(hi);
                const double value = f[c];
                const double below = hasLo ? f[grid.cellIndex(lo[0], lo[1], lo[2])] : value;
                const double above = hasHi ? f[grid.cellIndex(hi[0], hi[1], hi[2])] : value;
                const int span = int(hasLo) + int(hasHi);
                if (span > 0) d[c] = (above - below) / (span * grid.spacing[b]);
            }
    return d;
}

}  // namespace

FullTensorCoefficients gridAdvectionCoefficients(const BasisCache& cache, int count) {
    const VelocityBasis basis(cache);
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const int dim = grid.dim;
    const auto cells = Eigen::Index(grid.cellCount());
    Eigen::VectorXd weight(cells);
    for (Eigen::Index c = 0; c < cells; ++c)
        weight[c] = cache.cellFraction[std::size_t(c)] * grid.cellVolume();
    // U: (dim·cells) × N cell velocities; dU[b]: their derivatives along b.
    Eigen::MatrixXd u(dim * cells, count);
    std::vector<Eigen::MatrixXd> du(std::size_t(dim), Eigen::MatrixXd(dim * cells, count));
    for (int m = 0; m < count; ++m) {
        const CellField field = cellVelocity(basis, grid, m);
        for (int a = 0; a < dim; ++a) {
            u.col(m).segment(a * cells, cells) = field[std::size_t(a)];
            for (int b = 0; b < dim; ++b)
                du[std::size_t(b)].col(m).segment(a * cells, cells) =
                    derivative(grid, cache.cellFraction, field[std::size_t(a)], b);
        }
    }
    Eigen::MatrixXd weightedU = u;
    for (int a = 0; a < dim; ++a)
        for (int m = 0; m < count; ++m)
            weightedU.col(m).segment(a * cells, cells).array() *= weight.array();
    std::vector<double> full(std::size_t(count) * count * count);
    Eigen::MatrixXd advected(dim * cells, count);
    for (int i = 0; i < count; ++i) {
        // (Ψ_i·∇)Ψ_j for every j, then −⟨Ψ_k, ·⟩ for every k.
        advected.setZero();
        for (int b = 0; b < dim; ++b) {
            const Eigen::VectorXd ui = u.col(i).segment(b * cells, cells);
            for (int a = 0; a < dim; ++a)
                advected.middleRows(a * cells, cells) +=
                    ui.asDiagonal() * du[std::size_t(b)].middleRows(a * cells, cells);
        }
        const Eigen::MatrixXd ckj = -weightedU.transpose() * advected;  // (k, j)
        for (int k = 0; k < count; ++k)
            for (int j = 0; j < count; ++j)
                full[(std::size_t(k) * count + i) * count + j] = ckj(k, j);
    }
    return FullTensorCoefficients(count, std::move(full));
}

}  // namespace modeflow::validate
