#include "precompute/dec/CubicalComplex.h"

namespace modeflow {

CubicalComplex::CubicalComplex(const GridSpec& grid) : mGrid(grid) {
    const int n = grid.dim;
    const unsigned all = (1u << n) - 1;
    for (int k = 0; k <= n; ++k) {
        if (k == n - 1) {
            // Faces ordered by normal axis: face type a = all axes but a.
            for (int a = 0; a < n; ++a) mTypes[k].push_back(all & ~(1u << a));
        } else if (k == 1 && n == 3) {
            for (int a = 0; a < 3; ++a) mTypes[k].push_back(1u << a);  // edges along x, y, z
        } else {
            mTypes[k].push_back(k == 0 ? 0u : all);
        }
        std::int64_t offset = 0;
        for (unsigned m : mTypes[k]) {
            mTypeOffset[m] = offset;
            offset += countOfType(m);
        }
        mCounts[k] = offset;
    }
}

Index3 CubicalComplex::extent(unsigned axes) const {
    Index3 e{1, 1, 1};
    for (int a = 0; a < mGrid.dim; ++a)
        e[a] = mGrid.resolution[a] + ((axes >> a) & 1u || mGrid.isPeriodic(a) ? 0 : 1);
    return e;
}

std::int64_t CubicalComplex::countOfType(unsigned axes) const {
    const Index3 e = extent(axes);
    return std::int64_t(e[0]) * e[1] * e[2];
}

std::int64_t CubicalComplex::index(const Element& e) const {
    const Index3 x = extent(e.axes);
    return mTypeOffset[e.axes] + (std::int64_t(e.pos[2]) * x[1] + e.pos[1]) * x[0] + e.pos[0];
}

Element CubicalComplex::element(int k, std::int64_t index) const {
    for (unsigned m : mTypes[k]) {
        const std::int64_t count = countOfType(m);
        if (index < mTypeOffset[m] + count) {
            std::int64_t local = index - mTypeOffset[m];
            const Index3 x = extent(m);
            Element e{m, {}};
            e.pos[0] = int(local % x[0]);
            local /= x[0];
            e.pos[1] = int(local % x[1]);
            e.pos[2] = int(local / x[1]);
            return e;
        }
    }
    return {};
}

bool CubicalComplex::onWall(const Element& e) const {
    for (int a = 0; a < mGrid.dim; ++a) {
        if ((e.axes >> a) & 1u || mGrid.isPeriodic(a)) continue;
        if ((e.pos[a] == 0 && !mGrid.isOpen(a, false)) ||
            (e.pos[a] == mGrid.resolution[a] && !mGrid.isOpen(a, true)))
            return true;
    }
    return false;
}

int CubicalComplex::wrap(int axis, int position) const {
    if (!mGrid.isPeriodic(axis)) return position;
    const int n = mGrid.resolution[axis];
    return ((position % n) + n) % n;
}

namespace {
// Reorienting faces by (-1)^normal turns the standard cubical signs into "flux along +normal".
int orientation(const CubicalComplex& c, unsigned axes) {
    const int k = popcount(axes);
    if (k != c.dim() - 1) return 1;
    const unsigned all = (1u << c.dim()) - 1;
    const int normal = __builtin_ctz(all & ~axes);
    return normal % 2 ? -1 : 1;
}
}  // namespace

SparseMatrix CubicalComplex::incidence(int k) const {
    using Triplet = Eigen::Triplet<double, std::int64_t>;
    std::vector<Triplet> triplets;
    triplets.reserve(size_t(mCounts[k]) * 2 * (mGrid.dim - k));
    for (unsigned m : mTypes[k]) {
        const Index3 x = extent(m);
        for (int kk = 0; kk < x[2]; ++kk)
            for (int j = 0; j < x[1]; ++j)
                for (int i = 0; i < x[0]; ++i) {
                    const Element s{m, {i, j, kk}};
                    const std::int64_t col = index(s);
                    for (int a = 0; a < mGrid.dim; ++a) {
                        if ((m >> a) & 1u) continue;
                        const unsigned tm = m | (1u << a);
                        // Standard cubical sign: (-1)^(number of axes of s below a).
                        const int below = popcount(m & ((1u << a) - 1));
                        const int base =
                            (below % 2 ? -1 : 1) * orientation(*this, m) * orientation(*this, tm);
                        // s is the lower face of the (k+1)-cell at s.pos ...
                        if (s.pos[a] < mGrid.resolution[a])
                            triplets.emplace_back(index(Element{tm, s.pos}), col, -base);
                        // ... and the upper face of the one at s.pos - e_a (across the seam
                        // on a periodic axis).
                        if (s.pos[a] > 0 || mGrid.isPeriodic(a)) {
                            Element t{tm, s.pos};
                            t.pos[a] = wrap(a, s.pos[a] - 1);
                            triplets.emplace_back(index(t), col, base);
                        }
                    }
                }
    }
    SparseMatrix d(mCounts[k + 1], mCounts[k]);
    d.setFromTriplets(triplets.begin(), triplets.end());
    return d;
}

}  // namespace modeflow
