/// @file StrokeSplats.cpp

#include "engine/stir/StrokeSplats.h"

#include <algorithm>
#include <cmath>

namespace modeflow::stir {

std::vector<ForceSplat> strokeSplats(const Vec3& from, const Vec3& to, double elapsed,
                                     double radius, double force) {
    const double length =
        std::sqrt((to[0] - from[0]) * (to[0] - from[0]) + (to[1] - from[1]) * (to[1] - from[1]) +
                  (to[2] - from[2]) * (to[2] - from[2]));
    if (length == 0.0 || !(elapsed > 0.0)) return {};
    const int count = std::clamp(int(std::ceil(length / (2.0 * radius))), 1, 8);
    std::vector<ForceSplat> splats;
    for (int s = 1; s <= count; ++s) {
        const double t = double(s) / count;
        ForceSplat splat;
        splat.radius = radius;
        for (int a = 0; a < 3; ++a) {
            splat.centre[a] = from[a] + t * (to[a] - from[a]);
            splat.force[a] = force * (to[a] - from[a]) / elapsed;
        }
        splats.push_back(splat);
    }
    return splats;
}

}  // namespace modeflow::stir
