#include "precompute/dec/CutCellMeasures.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "precompute/dec/PeriodicSeams.h"
#include "precompute/dec/SimplexFraction.h"

namespace modeflow {

double insideTolerance(const GridSpec& grid) {
    double h = grid.spacing(0);
    for (int a = 1; a < grid.dim; ++a) h = std::min(h, grid.spacing(a));
    return 1e-10 * h;
}

Vec3 subLatticePoint(const GridSpec& grid, const Index3& pos, const Index3& sub, int subsamples) {
    Vec3 p{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a) {
        const double hs = grid.spacing(a) / subsamples;
        p[a] = grid.boundsMin[a] + double(std::int64_t(pos[a]) * subsamples + sub[a]) * hs;
    }
    return p;
}

namespace {

Vec3 elementCentre(const GridSpec& grid, const Element& e) {
    Vec3 c{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a)
        c[a] = grid.boundsMin[a] + (e.pos[a] + ((e.axes >> a) & 1u ? 0.5 : 0.0)) * grid.spacing(a);
    return c;
}

double circumradius(const GridSpec& grid, unsigned axes) {
    double r2 = 0.0;
    for (int a = 0; a < grid.dim; ++a)
        if ((axes >> a) & 1u) r2 += grid.spacing(a) * grid.spacing(a);
    return 0.5 * std::sqrt(r2);
}

/// Fraction of one element from χ sampled on its sub-lattice and Kuhn simplices.
class ElementSampler {
public:
    ElementSampler(const GridSpec& grid, const Domain& domain, unsigned axes, int subsamples)
        : mGrid(grid), mDomain(domain), mS(subsamples), mTol(insideTolerance(grid)) {
        for (int a = 0; a < grid.dim; ++a)
            if ((axes >> a) & 1u) mAxes.push_back(a);
        mK = int(mAxes.size());
        mPerm.resize(mK);
        std::iota(mPerm.begin(), mPerm.end(), 0);
        mPermutations.clear();
        do mPermutations.push_back(mPerm);
        while (std::next_permutation(mPerm.begin(), mPerm.end()));
        const int n = mS + 1;
        mValues.resize(size_t(mK >= 1 ? n : 1) * (mK >= 2 ? n : 1) * (mK >= 3 ? n : 1));
    }

    double fraction(const Element& e) {
        const int n = mS + 1;
        const int n1 = mK >= 2 ? n : 1, n2 = mK >= 3 ? n : 1, n0 = mK >= 1 ? n : 1;
        bool anyInside = false, allInside = true;
        for (int w = 0; w < n2; ++w)
            for (int v = 0; v < n1; ++v)
                for (int u = 0; u < n0; ++u) {
                    Index3 sub{0, 0, 0};
                    const int local[3] = {u, v, w};
                    for (int i = 0; i < mK; ++i) sub[mAxes[i]] = local[i];
                    double chi = mDomain.chi(subLatticePoint(mGrid, e.pos, sub, mS));
                    if (std::abs(chi) <= mTol) chi = 0.0;  // on the wall: Ω is open
                    anyInside |= chi > 0.0;
                    allInside &= chi > 0.0;
                    mValues[(size_t(w) * n1 + v) * n0 + u] = chi;
                }
        if (!anyInside) return 0.0;
        if (allInside) return 1.0;
        if (mK == 0) return 1.0;

        double sum = 0.0;
        std::array<double, 4> simplex{};
        std::array<Index3, 4> corner{};
        const int b1 = mK >= 2 ? mS : 1, b2 = mK >= 3 ? mS : 1;
        for (int w = 0; w < b2; ++w)
            for (int v = 0; v < b1; ++v)
                for (int u = 0; u < mS; ++u)
                    for (const auto& perm : mPermutations) {
                        int c[3] = {u, v, w};
                        bool touchesWall = false, positive = false;
                        for (int i = 0; i <= mK; ++i) {
                            if (i > 0) ++c[perm[i - 1]];
                            simplex[i] = mValues[(size_t(c[2]) * n1 + c[1]) * n0 + c[0]];
                            corner[i] = {c[0], c[1], c[2]};
                            touchesWall |= simplex[i] == 0.0;
                            positive |= simplex[i] > 0.0;
                        }
                        const std::span<const double> values(simplex.data(), mK + 1);
                        sum += (touchesWall && !positive) ? wallSimplexFraction(e, values, corner)
                                                          : positiveFraction(values);
                    }
        const double cells = double(mPermutations.size()) * std::pow(double(mS), mK);
        return std::clamp(sum / cells, 0.0, 1.0);
    }

private:
    /// A simplex whose vertices all lie on the wall or outside can still be inside Ω (at a
    /// convex corner of a box, χ is not linear and all three corners of a triangle lie on the
    /// two walls). Its centroid decides: when it is inside, the simplex is split at the centroid
    /// into k+1 equal simplices measured with that extra sample.
    double wallSimplexFraction(const Element& e, std::span<const double> values,
                               const std::array<Index3, 4>& corner) const {
        Vec3 centroid{0.0, 0.0, 0.0};
        for (int i = 0; i <= mK; ++i) {
            Index3 sub{0, 0, 0};
            for (int j = 0; j < mK; ++j) sub[mAxes[j]] = corner[i][j];
            const Vec3 p = subLatticePoint(mGrid, e.pos, sub, mS);
            for (int a = 0; a < 3; ++a) centroid[a] += p[a] / (mK + 1);
        }
        const double chi = mDomain.chi(centroid);
        if (chi <= mTol) return 0.0;
        double sum = 0.0;
        std::array<double, 4> part{};
        for (int drop = 0; drop <= mK; ++drop) {
            int j = 0;
            for (int i = 0; i <= mK; ++i)
                if (i != drop) part[j++] = values[i];
            part[j] = chi;
            sum += positiveFraction(std::span<const double>(part.data(), mK + 1));
        }
        return sum / (mK + 1);
    }

    const GridSpec& mGrid;
    const Domain& mDomain;
    int mS;
    double mTol;
    std::vector<int> mAxes;
    int mK = 0;
    std::vector<int> mPerm;
    std::vector<std::vector<int>> mPermutations;
    std::vector<double> mValues;
};

void measureStaircase(const CubicalComplex& cx, const Domain& domain, CutCellMeasures& m) {
    const GridSpec& grid = cx.grid();
    const int n = grid.dim;
    const double tol = insideTolerance(grid);
    auto& cells = m.fraction[n];
    cells.assign(size_t(cx.count(n)), 0.0);
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < cx.count(n); ++c)
        cells[c] = domain.chi(elementCentre(grid, cx.element(n, c))) > tol ? 1.0 : 0.0;

    for (int k = 0; k < n; ++k) {
        auto& f = m.fraction[k];
        f.assign(size_t(cx.count(k)), 0.0);
#pragma omp parallel for schedule(static)
        for (std::int64_t id = 0; id < cx.count(k); ++id) {
            const Element e = cx.element(k, id);
            if (cx.onWall(e)) continue;
            // All 2^(n-k) cells whose closure holds e must be inside (beyond an open side there
            // is no cell: the air goes on).
            std::vector<int> free;
            for (int a = 0; a < n; ++a)
                if (!((e.axes >> a) & 1u)) free.push_back(a);
            bool inside = true;
            for (unsigned corner = 0; corner < (1u << free.size()) && inside; ++corner) {
                Element cell{(1u << n) - 1, e.pos};
                bool beyond = false;
                for (size_t i = 0; i < free.size(); ++i) {
                    const int a = free[i];
                    if ((corner >> i) & 1u) cell.pos[a] = cx.wrap(a, cell.pos[a] - 1);
                    beyond |= cell.pos[a] < 0 || cell.pos[a] == grid.resolution[a];
                }
                if (!beyond) inside = cells[cx.index(cell)] > 0.0;
            }
            f[id] = inside ? 1.0 : 0.0;
        }
    }
}

/// A face is a flux DOF only between two cells with fluid. Sampling guarantees it almost
/// always; the centroid rule of wallSimplexFraction can leave a face whose neighbour measured 0.
void dropFacesBesideEmptyCells(const CubicalComplex& cx, CutCellMeasures& m) {
    const int n = cx.dim();
    const SparseMatrix d = cx.incidence(n - 1);
    for (std::int64_t c = 0; c < cx.count(n); ++c) {
        if (m.fraction[n][c] > 0.0) continue;
        for (SparseMatrix::InnerIterator it(d, c); it; ++it) m.fraction[n - 1][it.col()] = 0.0;
    }
}

void measureCut(const CubicalComplex& cx, const Domain& domain, int subsamples,
                CutCellMeasures& m) {
    const GridSpec& grid = cx.grid();
    const double tol = insideTolerance(grid);
    for (int k = 0; k <= grid.dim; ++k) {
        auto& f = m.fraction[k];
        f.assign(size_t(cx.count(k)), 0.0);
        for (unsigned axes : cx.types(k)) {
            const double radius = circumradius(grid, axes);
            const std::int64_t begin = cx.index(Element{axes, {0, 0, 0}});
            const std::int64_t end = begin + cx.countOfType(axes);
#pragma omp parallel
            {
                ElementSampler sampler(grid, domain, axes, subsamples);
#pragma omp for schedule(dynamic, 256)
                for (std::int64_t id = begin; id < end; ++id) {
                    const Element e = cx.element(k, id);
                    if (k < grid.dim && cx.onWall(e)) continue;
                    const double chi = domain.chi(elementCentre(grid, e));
                    if (chi > radius + tol)
                        f[id] = 1.0;
                    else if (chi < -(radius + tol))
                        f[id] = 0.0;
                    else
                        f[id] = sampler.fraction(e);
                }
            }
        }
    }
    dropFacesBesideEmptyCells(cx, m);
}

/// Fills m.sideFraction: each face on a side of the box along its normal, measured as the faces
/// inside are (cut: sampled; staircase: as the one cell beside it), and 0 beside an empty cell.
void measureSideFaces(const CubicalComplex& cx, const Domain& domain, BoundaryTreatment treatment,
                      int subsamples, CutCellMeasures& m) {
    const GridSpec& grid = cx.grid();
    const int n = grid.dim;
    const double tol = insideTolerance(grid);
    m.sideFraction.assign(std::size_t(cx.count(n - 1)), 0.0);
    for (int a = 0; a < n; ++a) {
        const unsigned axes = cx.types(n - 1)[std::size_t(a)];  // type a has normal a
        const double radius = circumradius(grid, axes);
        ElementSampler sampler(grid, domain, axes, subsamples);
        cx.forEachSideFace(a, [&](const Element& face, const Element& cell) {
            if (m.fraction[n][cx.index(cell)] <= 0.0) return;
            double f = 1.0;
            if (treatment != BoundaryTreatment::Staircase) {
                const double chi = domain.chi(elementCentre(grid, face));
                f = chi > radius + tol ? 1.0 : chi < -(radius + tol) ? 0.0 : sampler.fraction(face);
            }
            if (f > 0.0)
                m.sideFraction[std::size_t(cx.index(face))] =
                    std::max(f, CutCellMeasures::kMinFraction);
        });
    }
}

}  // namespace

CutCellMeasures measureCutCells(const CubicalComplex& complex, const Domain& domain,
                                BoundaryTreatment treatment, int subsamples) {
    requireDomainAgreesAcrossSeams(complex, domain, subsamples);
    CutCellMeasures m;
    if (treatment == BoundaryTreatment::Staircase)
        measureStaircase(complex, domain, m);
    else
        measureCut(complex, domain, subsamples, m);
    requireNoWallOnSeams(complex, m);
    for (auto& f : m.fraction)
        for (double& x : f)
            if (x > 0.0) x = std::max(x, CutCellMeasures::kMinFraction);
    measureSideFaces(complex, domain, treatment, subsamples, m);
    return m;
}

}  // namespace modeflow
