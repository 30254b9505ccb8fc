#include "engine/core/MacGrid.h"

#include "engine/core/Error.h"

namespace modeflow {

MacGrid MacGrid::fromSpec(const GridSpec& grid) {
    MacGrid mac;
    mac.dim = grid.dim;
    for (int a = 0; a < grid.dim; ++a) {
        mac.cells[a] = grid.resolution[a];
        mac.origin[a] = grid.boundsMin[a];
        mac.spacing[a] = grid.spacing(a);
    }
    return mac;
}

MacGrid MacGrid::refined(int scale) const {
    if (scale < 1) throw Error("smoke resolution scale must be at least 1, got " + std::to_string(scale));
    MacGrid fine = *this;
    for (int a = 0; a < dim; ++a) {
        fine.cells[a] = cells[a] * scale;
        fine.spacing[a] = spacing[a] / scale;
    }
    return fine;
}

double MacGrid::faceArea(int axis) const {
    double area = 1.0;
    for (int a = 0; a < dim; ++a)
        if (a != axis) area *= spacing[a];
    return area;
}

}  // namespace modeflow
