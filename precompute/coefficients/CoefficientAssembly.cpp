#include "precompute/coefficients/CoefficientAssembly.h"

#include <algorithm>

#include <cblas.h>

#include <Eigen/SparseCore>

#include "engine/core/PackedLayout.h"

namespace modeflow {
namespace {

using Triplet = Eigen::Triplet<double>;
using ColSparse = Eigen::SparseMatrix<double>;

/// Linear maps from face fluxes to weighted vorticity and to the two velocity components at the
/// vorticity elements of one type (only elements with positive weight are kept).
struct ElementSampling {
    ColSparse vorticity;  ///< w_e ω(e)
    ColSparse velocityB;  ///< u_b(e)
    ColSparse velocityC;  ///< u_c(e)
};

ElementSampling sampleElements(const CubicalComplex& cx, const CutCellMeasures& measures,
                               const CutCellDec& dec, unsigned axes, int b, int c) {
    const GridSpec& grid = cx.grid();
    const int n = grid.dim;
    const unsigned all = (1u << n) - 1;
    std::vector<Triplet> omega, ub, uc;
    std::int64_t rows = 0;

    // Face DOF beside `pos` with the given normal, or -1 (outside the grid or not a DOF). On a
    // periodic axis the neighbour lies across the seam.
    auto faceDof = [&](Index3 pos, int normal) -> std::int64_t {
        const unsigned axes = all & ~(1u << normal);
        const Index3 extent = cx.extent(axes);
        for (int a = 0; a < n; ++a) {
            pos[a] = cx.wrap(a, pos[a]);
            if (pos[a] < 0 || pos[a] >= extent[a]) return -1;
        }
        return dec.faces.toLocal[cx.index(Element{axes, pos})];
    };
    auto faceStar = [&](std::int64_t dof) { return dec.faceStar[dof]; };
    auto faceVelocity = [&](std::int64_t dof) {
        // flux / |face ∩ Ω| = ⋆Ψ / |dual edge|
        const Element f = cx.element(n - 1, dec.faces.toGlobal[dof]);
        return faceStar(dof) / dualMeasure(grid, f);
    };

    const Index3 extent = cx.extent(axes);
    for (int k = 0; k < extent[2]; ++k)
        for (int j = 0; j < extent[1]; ++j)
            for (int i = 0; i < extent[0]; ++i) {
                const Element e{axes, {i, j, k}};
                const double fraction = measures.fraction[n - 2][cx.index(e)];
                if (fraction <= 0.0) continue;
                const double dualArea = dualMeasure(grid, e);
                const double weight = fraction * primalMeasure(grid, axes) * dualArea;
                Index3 minusB = e.pos, minusC = e.pos;
                --minusB[b];
                --minusC[c];
                // ∂_b u_c: c-normal faces on the +b side (at pos) and -b side (pos - e_b).
                // −∂_c u_b: b-normal faces on the +c side (at pos) and -c side (pos - e_c).
                const std::pair<std::int64_t, double> circulation[4] = {{faceDof(e.pos, c), 1.0},
                                                                        {faceDof(minusB, c), -1.0},
                                                                        {faceDof(e.pos, b), -1.0},
                                                                        {faceDof(minusC, b), 1.0}};
                for (const auto& [dof, sign] : circulation)
                    if (dof >= 0)
                        omega.emplace_back(rows, dof, weight * sign * faceStar(dof) / dualArea);
                for (std::int64_t dof : {faceDof(e.pos, b), faceDof(minusC, b)})
                    if (dof >= 0) ub.emplace_back(rows, dof, 0.5 * faceVelocity(dof));
                for (std::int64_t dof : {faceDof(e.pos, c), faceDof(minusB, c)})
                    if (dof >= 0) uc.emplace_back(rows, dof, 0.5 * faceVelocity(dof));
                ++rows;
            }
    ElementSampling s;
    const auto cols = Eigen::Index(dec.faces.size());
    s.vorticity.resize(rows, cols);
    s.vorticity.setFromTriplets(omega.begin(), omega.end());
    s.velocityB.resize(rows, cols);
    s.velocityB.setFromTriplets(ub.begin(), ub.end());
    s.velocityC.resize(rows, cols);
    s.velocityC.setFromTriplets(uc.begin(), uc.end());
    return s;
}

/// Appends the rows of `m` to `rows`.
void appendRows(const ColSparse& m, SparseRows& rows) {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> byRow = m;
    for (Eigen::Index r = 0; r < byRow.outerSize(); ++r) {
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(byRow, r); it; ++it) {
            rows.column.push_back(std::int32_t(it.col()));
            rows.value.push_back(it.value());
        }
        rows.start.push_back(std::int64_t(rows.value.size()));
    }
}

/// Rows [first, first + count) of `rows` as a column-major sparse matrix with `columns` columns.
ColSparse rowBlock(const SparseRows& rows, std::int64_t first, std::int64_t count,
                   Eigen::Index columns) {
    std::vector<Triplet> entries;
    entries.reserve(std::size_t(rows.start[first + count] - rows.start[first]));
    for (std::int64_t r = 0; r < count; ++r)
        for (std::int64_t t = rows.start[first + r]; t < rows.start[first + r + 1]; ++t)
            entries.emplace_back(Eigen::Index(r), rows.column[t], rows.value[t]);
    ColSparse m(Eigen::Index(count), columns);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;
}

/// Elements whose samples are held at once: 3 × this × N doubles, and the products of 256 pairs
/// (32 MB; 128 MB at 2¹⁶ elements, whose writes and reads then took longer).
constexpr std::int64_t kElementBlock = 1 << 14;

}  // namespace

void accumulateCrossProducts(const Eigen::MatrixXd& omega, const Eigen::MatrixXd& p,
                             const Eigen::MatrixXd& q, std::vector<double>& packed) {
    const int modes = int(p.cols());
    const Eigen::Index elements = p.rows();
    const std::size_t pairs = pairCount(std::size_t(modes));
    std::vector<int> pairK(pairs), pairJ(pairs);
    for (int k = 0, at = 0; k < modes; ++k)
        for (int j = k + 1; j < modes; ++j, ++at) pairK[at] = k, pairJ[at] = j;

    Eigen::Map<Eigen::MatrixXd> out(packed.data(), modes, Eigen::Index(pairs));
    constexpr Eigen::Index kBlock = 256;
    Eigen::MatrixXd r(elements, kBlock);
    for (Eigen::Index start = 0; start < Eigen::Index(pairs); start += kBlock) {
        const Eigen::Index count = std::min<Eigen::Index>(kBlock, Eigen::Index(pairs) - start);
#pragma omp parallel for schedule(static)
        for (Eigen::Index m = 0; m < count; ++m) {
            const int k = pairK[size_t(start + m)], j = pairJ[size_t(start + m)];
            r.col(m) = p.col(k).cwiseProduct(q.col(j)) - q.col(k).cwiseProduct(p.col(j));
        }
        // out += ωᵀ r by OpenBLAS, on every core (with kElementBlock, 7% faster than Eigen's
        // product on blocks of 2¹⁶ elements: N = 230, 147 k elements, 37 s against 40 s).
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, modes, int(count), int(elements), 1.0,
                    omega.data(), int(omega.outerStride()), r.data(), int(r.outerStride()), 1.0,
                    out.col(start).data(), int(out.outerStride()));
    }
}

BasisCache::Quadrature vorticityQuadrature(const CubicalComplex& complex,
                                           const CutCellMeasures& measures, const CutCellDec& dec) {
    const int n = complex.dim();
    BasisCache::Quadrature q;
    for (unsigned axes : complex.types(n - 2)) {
        // 3D: edge along a, (b, c) = (a+1, a+2) mod 3. 2D: vertices, (b, c) = (x, y).
        const int a = n == 3 ? __builtin_ctz(axes) : 2;
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const ElementSampling s = sampleElements(complex, measures, dec, axes, b, c);
        appendRows(s.vorticity, q.curl);
        appendRows(s.velocityB, q.velocityB);
        appendRows(s.velocityC, q.velocityC);
    }
    return q;
}

std::vector<double> assembleStructuralCoefficients(const BasisCache::Quadrature& quadrature,
                                                   const Eigen::MatrixXd& modes) {
    std::vector<double> packed(packedSize(std::size_t(modes.cols())), 0.0);
    if (modes.cols() < 2) return packed;
    const std::int64_t elements = quadrature.curl.rows();
    for (std::int64_t first = 0; first < elements; first += kElementBlock) {
        const std::int64_t count = std::min(kElementBlock, elements - first);
        const Eigen::MatrixXd omega = rowBlock(quadrature.curl, first, count, modes.rows()) * modes;
        const Eigen::MatrixXd p =
            rowBlock(quadrature.velocityB, first, count, modes.rows()) * modes;
        const Eigen::MatrixXd q =
            rowBlock(quadrature.velocityC, first, count, modes.rows()) * modes;
        accumulateCrossProducts(omega, p, q, packed);
    }
    return packed;
}

std::vector<double> assembleStructuralCoefficients(const CubicalComplex& complex,
                                                   const CutCellMeasures& measures,
                                                   const CutCellDec& dec,
                                                   const Eigen::MatrixXd& modes) {
    return assembleStructuralCoefficients(vorticityQuadrature(complex, measures, dec), modes);
}

}  // namespace modeflow
