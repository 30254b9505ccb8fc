#include "engine/simulation/SolidLevelSet.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace modeflow {

double SolidLevelSet::depthAt(const Vec3& p) const {
    std::array<int, 3> i{};
    std::array<double, 3> f{};
    for (int a = 0; a < 3; ++a) {
        const double x = (p[a] - origin[a]) / spacing;
        // The last sample pair's cell holds x = samples − 1 too.
        if (!(x >= 0.0) || x > double(samples[a] - 1)) return -spacing;
        i[a] = std::min(int(x), samples[a] - 2);
        f[a] = x - i[a];
    }
    const auto at = [&](int x, int y, int z) {
        return double(depth[std::size_t(x) +
                            std::size_t(samples[0]) *
                                (std::size_t(y) + std::size_t(samples[1]) * std::size_t(z))]);
    };
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
        const double w =
            (dx ? f[0] : 1.0 - f[0]) * (dy ? f[1] : 1.0 - f[1]) * (dz ? f[2] : 1.0 - f[2]);
        sum += w * at(i[0] + dx, i[1] + dy, i[2] + dz);
    }
    return sum;
}

}  // namespace modeflow
