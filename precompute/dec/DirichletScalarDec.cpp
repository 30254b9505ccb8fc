#include "precompute/dec/DirichletScalarDec.h"

#include <algorithm>
#include <cmath>

namespace modeflow {
namespace {

Vec3 cellCentre(const GridSpec& grid, const Index3& pos) {
    Vec3 c{0.0, 0.0, 0.0};
    for (int a = 0; a < grid.dim; ++a) c[a] = grid.boundsMin[a] + (pos[a] + 0.5) * grid.spacing(a);
    return c;
}

/// χ with the grid box's walls included (periodic axes have none: a point past the seam is
/// brought back into the box).
double chiInBox(const GridSpec& grid, const Domain& domain, Vec3 p) {
    for (int a = 0; a < grid.dim; ++a) {
        if (!grid.isPeriodic(a)) continue;
        const double length = grid.boundsMax[a] - grid.boundsMin[a];
        p[a] -= length * std::floor((p[a] - grid.boundsMin[a]) / length);
    }
    double box = domain.chi(p);
    for (int a = 0; a < grid.dim; ++a)
        if (!grid.isPeriodic(a))
            box = std::min({box, p[a] - grid.boundsMin[a], grid.boundsMax[a] - p[a]});
    return box;
}

/// Fraction of the segment inside → outside before χ crosses zero (bisection: χ is not linear).
double wallFraction(const GridSpec& grid, const Domain& domain, const Vec3& inside,
                    const Vec3& outside) {
    double lo = 0.0, hi = 1.0;
    auto at = [&](double t) {
        Vec3 p;
        for (int a = 0; a < 3; ++a) p[a] = inside[a] + t * (outside[a] - inside[a]);
        return chiInBox(grid, domain, p);
    };
    const double tol = insideTolerance(grid);
    for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        (at(mid) > tol ? lo : hi) = mid;
    }
    return std::max(0.5 * (lo + hi), CutCellMeasures::kMinFraction);
}

}  // namespace

DirichletScalarDec buildDirichletScalarDec(const CubicalComplex& cx, const Domain& domain,
                                           BoundaryTreatment treatment) {
    const GridSpec& grid = cx.grid();
    const int n = grid.dim;
    const double tol = insideTolerance(grid);
    // One byte per cell while threads write: std::vector<bool> packs neighbours into one word,
    // and concurrent writes to it race (cells went missing at random on small grids).
    std::vector<char> insideByte(size_t(cx.count(n)));
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < cx.count(n); ++c)
        insideByte[c] = chiInBox(grid, domain, cellCentre(grid, cx.element(n, c).pos)) > tol;
    const std::vector<bool> inside(insideByte.begin(), insideByte.end());

    DirichletScalarDec dec;
    dec.grid = grid;
    dec.cells = DofMap::fromMask(inside);
    const double cellVolume = primalMeasure(grid, (1u << n) - 1);
    dec.cellStar = Eigen::VectorXd::Constant(dec.cells.size(), 1.0 / cellVolume);

    // Faces are columns of d_{n-1}: walk the transpose to find the cells beside each face.
    const SparseMatrix dT = cx.incidence(n - 1).transpose();
    using Triplet = Eigen::Triplet<double, std::int64_t>;
    std::vector<Triplet> triplets;
    std::vector<double> weights;
    for (std::int64_t f = 0; f < cx.count(n - 1); ++f) {
        const Element face = cx.element(n - 1, f);
        const int normal = __builtin_ctz(((1u << n) - 1) & ~face.axes);
        Index3 below = face.pos, above = face.pos;
        below[normal] = cx.wrap(normal, below[normal] - 1);
        const bool hasBelow = below[normal] >= 0,
                   hasAbove = face.pos[normal] < grid.resolution[normal];
        const std::int64_t cb = hasBelow ? cx.index(Element{(1u << n) - 1, below}) : -1;
        const std::int64_t ca = hasAbove ? cx.index(Element{(1u << n) - 1, above}) : -1;
        const bool inB = cb >= 0 && inside[cb], inA = ca >= 0 && inside[ca];
        if (!inB && !inA) continue;
        double theta = 1.0;
        if (!(inB && inA) && treatment == BoundaryTreatment::Staircase) {
            theta = 0.5;
        } else if (!(inB && inA)) {
            const Vec3 from = cellCentre(grid, inB ? below : above);
            Vec3 to = from;
            to[normal] += (inB ? 1.0 : -1.0) * grid.spacing(normal);
            theta = wallFraction(grid, domain, from, to);
        }
        const std::int64_t col = std::int64_t(weights.size());
        weights.push_back(primalMeasure(grid, face.axes) / (theta * grid.spacing(normal)));
        dec.faces.push_back(f);
        for (SparseMatrix::InnerIterator it(dT, f); it; ++it) {
            const std::int64_t r = dec.cells.toLocal[it.col()];
            if (r >= 0) triplets.emplace_back(r, col, it.value());
        }
    }
    dec.div.resize(dec.cells.size(), std::int64_t(weights.size()));
    dec.div.setFromTriplets(triplets.begin(), triplets.end());
    dec.faceWeight = Eigen::Map<Eigen::VectorXd>(weights.data(), Eigen::Index(weights.size()));
    return dec;
}

}  // namespace modeflow
