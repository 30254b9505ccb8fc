#include "precompute/dec/PeriodicSeams.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/NumberText.h"

namespace modeflow {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

std::string pointText(const Vec3& p, int dim) {
    std::string text = "(";
    for (int a = 0; a < dim; ++a) text += (a ? ", " : "") + numberText(p[a], 6);
    return text + ")";
}

std::string inOrOut(bool inside) {
    return inside ? "inside" : "outside";
}

}  // namespace

void requireDomainAgreesAcrossSeams(const CubicalComplex& complex, const Domain& domain,
                                    int subsamples) {
    const GridSpec& grid = complex.grid();
    if (!grid.anyPeriodic() || domain.isWholeBox()) return;
    const double tol = insideTolerance(grid);
    for (int a = 0; a < grid.dim; ++a) {
        if (!grid.isPeriodic(a)) continue;
        // The seam's sub-lattice points: subsamples per cell along the other axes, ends included.
        Index3 points{1, 1, 1};
        for (int b = 0; b < grid.dim; ++b)
            if (b != a) points[b] = grid.resolution[b] * subsamples + 1;
        for (int k = 0; k < points[2]; ++k)
            for (int j = 0; j < points[1]; ++j)
                for (int i = 0; i < points[0]; ++i) {
                    Index3 sub{i, j, k}, atMin{0, 0, 0}, atMax{0, 0, 0};
                    sub[a] = 0;
                    atMax[a] = grid.resolution[a];
                    const Vec3 low = subLatticePoint(grid, atMin, sub, subsamples);
                    const Vec3 high = subLatticePoint(grid, atMax, sub, subsamples);
                    const bool lowInside = domain.chi(low) > tol,
                               highInside = domain.chi(high) > tol;
                    if (lowInside == highInside) continue;
                    const std::string axis = kAxisNames[a];
                    throw Error("[[domain]]: the domain does not repeat across periodic axis " +
                                axis + ": " + pointText(low, grid.dim) + " is " +
                                inOrOut(lowInside) + " and " + pointText(high, grid.dim) + " " +
                                inOrOut(highInside) +
                                ", but they are the same point of the periodic box; make the "
                                "shapes agree at " +
                                axis + " = " + numberText(grid.boundsMin[a], 6) + " and " + axis +
                                " = " + numberText(grid.boundsMax[a], 6) +
                                " (or set [grid].periodic false on " + axis + ")");
                }
    }
}

void requireNoWallOnSeams(const CubicalComplex& complex, const CutCellMeasures& measures) {
    const GridSpec& grid = complex.grid();
    const int n = grid.dim;
    if (!grid.anyPeriodic()) return;
    const unsigned all = (1u << n) - 1;
    const auto whole = [&](const Element& cell) {
        return measures.fraction[n][complex.index(cell)] > 1.0 - 1e-9;
    };
    for (int a = 0; a < n; ++a) {
        if (!grid.isPeriodic(a)) continue;
        const unsigned faceAxes = all & ~(1u << a);
        Index3 seam = complex.extent(faceAxes);
        seam[a] = 1;  // the faces at position 0 along a
        for (int k = 0; k < seam[2]; ++k)
            for (int j = 0; j < seam[1]; ++j)
                for (int i = 0; i < seam[0]; ++i) {
                    const Element face{faceAxes, {i, j, k}};
                    Element below{all, face.pos};
                    below.pos[a] = grid.resolution[a] - 1;
                    if (measures.fraction[n - 1][complex.index(face)] > 0.0 || !whole(below) ||
                        !whole(Element{all, face.pos}))
                        continue;
                    const std::string axis = kAxisNames[a];
                    throw Error(
                        "[[domain]]: a wall of the domain lies on the seam of periodic axis " +
                        axis + " (the plane " + axis + " = " + numberText(grid.boundsMin[a], 6) +
                        ", which is " + axis + " = " + numberText(grid.boundsMax[a], 6) +
                        "), where a periodic box has none; let the shapes reach past the grid box "
                        "along " +
                        axis + " (or set [grid].periodic false on " + axis + ")");
                }
    }
}

}  // namespace modeflow
