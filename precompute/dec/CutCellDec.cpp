#include "precompute/dec/CutCellDec.h"

namespace modeflow {

DofMap DofMap::fromMask(const std::vector<bool>& isDof) {
    DofMap m;
    m.toLocal.assign(isDof.size(), -1);
    for (size_t i = 0; i < isDof.size(); ++i)
        if (isDof[i]) {
            m.toLocal[i] = std::int64_t(m.toGlobal.size());
            m.toGlobal.push_back(std::int64_t(i));
        }
    return m;
}

double primalMeasure(const GridSpec& grid, unsigned axes) {
    double m = 1.0;
    for (int a = 0; a < grid.dim; ++a)
        if ((axes >> a) & 1u) m *= grid.spacing(a);
    return m;
}

double dualMeasure(const GridSpec& grid, const Element& e) {
    double m = 1.0;
    for (int a = 0; a < grid.dim; ++a) {
        if ((e.axes >> a) & 1u) continue;
        const bool onWall =
            !grid.isPeriodic(a) && (e.pos[a] == 0 || e.pos[a] == grid.resolution[a]);
        m *= grid.spacing(a) * (onWall ? 0.5 : 1.0);
    }
    return m;
}

namespace {

/// Keeps the rows and columns of `d` that are DOFs.
SparseMatrix restrict(const SparseMatrix& d, const DofMap& rows, const DofMap& cols) {
    using Triplet = Eigen::Triplet<double, std::int64_t>;
    std::vector<Triplet> t;
    for (std::int64_t r = 0; r < rows.size(); ++r)
        for (SparseMatrix::InnerIterator it(d, rows.toGlobal[r]); it; ++it) {
            const std::int64_t c = cols.toLocal[it.col()];
            if (c >= 0) t.emplace_back(r, c, it.value());
        }
    SparseMatrix out(rows.size(), cols.size());
    out.setFromTriplets(t.begin(), t.end());
    return out;
}

std::vector<bool> positive(const std::vector<double>& f) {
    std::vector<bool> m(f.size());
    for (size_t i = 0; i < f.size(); ++i) m[i] = f[i] > 0.0;
    return m;
}

}  // namespace

CutCellDec buildCutCellDec(const CubicalComplex& cx, const CutCellMeasures& measures,
                           WallKind wall) {
    const GridSpec& grid = cx.grid();
    const int n = grid.dim;
    CutCellDec dec;
    dec.grid = grid;
    dec.wall = wall;
    dec.cells = DofMap::fromMask(positive(measures.fraction[n]));
    dec.faces = DofMap::fromMask(positive(measures.fraction[n - 1]));

    const SparseMatrix dCurlFull = cx.incidence(n - 2);  // rows: faces
    std::vector<bool> vortDof = positive(measures.fraction[n - 2]);
    if (wall == WallKind::NoSlip) {
        for (std::int64_t f : dec.faces.toGlobal)
            for (SparseMatrix::InnerIterator it(dCurlFull, f); it; ++it) vortDof[it.col()] = true;
    }
    dec.vorticity = DofMap::fromMask(vortDof);

    dec.div = restrict(cx.incidence(n - 1), dec.cells, dec.faces);
    dec.curl = restrict(dCurlFull, dec.faces, dec.vorticity);

    dec.cellStar.resize(dec.cells.size());
    for (std::int64_t i = 0; i < dec.cells.size(); ++i) {
        const std::int64_t g = dec.cells.toGlobal[i];
        dec.cellStar[i] =
            1.0 / (primalMeasure(grid, cx.element(n, g).axes) * measures.fraction[n][g]);
    }
    dec.faceStar.resize(dec.faces.size());
    for (std::int64_t i = 0; i < dec.faces.size(); ++i) {
        const std::int64_t g = dec.faces.toGlobal[i];
        const Element e = cx.element(n - 1, g);
        dec.faceStar[i] =
            dualMeasure(grid, e) / (primalMeasure(grid, e.axes) * measures.fraction[n - 1][g]);
    }
    dec.vorticityStarInverse.resize(dec.vorticity.size());
    for (std::int64_t i = 0; i < dec.vorticity.size(); ++i) {
        const std::int64_t g = dec.vorticity.toGlobal[i];
        const Element e = cx.element(n - 2, g);
        const double f = measures.fraction[n - 2][g];
        const double cut = (wall == WallKind::NoSlip && f == 0.0) ? 1.0 : f;
        dec.vorticityStarInverse[i] = primalMeasure(grid, e.axes) * cut / dualMeasure(grid, e);
    }
    return dec;
}

}  // namespace modeflow
