#include "engine/core/MacGrid.h"

#include <cmath>

#include "engine/core/Error.h"

namespace modeflow {

MacGrid MacGrid::fromSpec(const GridSpec& grid) {
    MacGrid mac;
    mac.dim = grid.dim;
    for (int a = 0; a < grid.dim; ++a) {
        mac.cells[a] = grid.resolution[a];
        mac.origin[a] = grid.boundsMin[a];
        mac.spacing[a] = grid.spacing(a);
        mac.periodic[a] = grid.isPeriodic(a);
    }
    mac.open = grid.open;
    return mac;
}

MacGrid MacGrid::refined(int scale) const {
    if (scale < 1)
        throw Error("smoke resolution scale must be at least 1, got " + std::to_string(scale));
    MacGrid fine = *this;
    for (int a = 0; a < dim; ++a) {
        fine.cells[a] = cells[a] * scale;
        fine.spacing[a] = spacing[a] / scale;
    }
    return fine;
}

Vec3 MacGrid::minimumImage(Vec3 offset) const {
    for (int a = 0; a < dim; ++a)
        if (periodic[a]) offset[a] -= length(a) * std::round(offset[a] / length(a));
    return offset;
}

Vec3 MacGrid::nearestImage(Vec3 point, const Vec3& to) const {
    for (int a = 0; a < dim; ++a)
        if (periodic[a]) point[a] -= length(a) * std::round((point[a] - to[a]) / length(a));
    return point;
}

double MacGrid::faceArea(int axis) const {
    double area = 1.0;
    for (int a = 0; a < dim; ++a)
        if (a != axis) area *= spacing[a];
    return area;
}

}  // namespace modeflow
