#pragma once
/// @file CutCellDec.h
/// Exterior derivatives and diagonal Hodge stars restricted to the degrees of freedom of a cut-cell
/// domain (precompute/README.md, seed §6.3.4, appendix C.1). In 3D: cells = 3-forms, faces =
/// 2-forms, edges = 1-forms (vorticity); in 2D: cells, faces (edges), vertices (vorticity).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellMeasures.h"

namespace modeflow {

/// Which elements of one dimension are degrees of freedom, both ways.
struct DofMap {
    std::vector<std::int64_t> toGlobal;  ///< DOF → element number in the complex
    std::vector<std::int64_t> toLocal;   ///< element number → DOF, or -1

    std::int64_t size() const { return std::int64_t(toGlobal.size()); }
    static DofMap fromMask(const std::vector<bool>& isDof);
};

struct CutCellDec {
    GridSpec grid;
    WallKind wall = WallKind::FreeSlip;
    DofMap cells;      ///< n-cells with positive measure
    DofMap faces;      ///< (n-1)-cells with positive measure, not on a wall of the grid box
    DofMap vorticity;  ///< (n-2)-cells with a non-zero ⋆⁻¹ (see buildCutCellDec)

    SparseMatrix div;   ///< d_{n-1}: faces → cells ("d2" in 3D), DOFs only
    SparseMatrix curl;  ///< d_{n-2}: vorticity elements → faces ("d1" in 3D), DOFs only

    Eigen::VectorXd cellStar;              ///< ⋆n = 1 / |cell ∩ Ω|
    Eigen::VectorXd faceStar;              ///< ⋆(n-1) = |dual edge| / |face ∩ Ω|
    Eigen::VectorXd vorticityStarInverse;  ///< ⋆(n-2)⁻¹ = |element ∩ Ω| / |dual|
};

/// Primal measure |element| (length, area, volume; 1 for a vertex) before cutting.
double primalMeasure(const GridSpec& grid, unsigned axes);
/// Dual measure of an element, clipped to the grid box (halved per axis where it lies on a wall;
/// never along a periodic axis, where the dual cell wraps across the seam).
double dualMeasure(const GridSpec& grid, const Element& e);

/// Assembles the restricted operators. Free-slip: vorticity elements with no measure inside Ω
/// get ⋆⁻¹ = 0 and drop out. No-slip: every vorticity element touching a face DOF keeps its full
/// primal measure, so the wall vorticity (the one-sided difference to the wall's zero velocity)
/// stays in the curl term.
CutCellDec buildCutCellDec(const CubicalComplex& complex, const CutCellMeasures& measures,
                           WallKind wall);

}  // namespace modeflow
