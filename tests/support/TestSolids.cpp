#include "tests/support/TestSolids.h"

#include <algorithm>
#include <cmath>

namespace modeflow::testing {

std::shared_ptr<const SolidLevelSet> lShapedLattice() {
    auto solid = std::make_shared<SolidLevelSet>();
    solid->spacing = 0.02;
    solid->origin = {-0.3, -0.3, -0.1};
    solid->samples = {31, 31, 11};
    const auto boxDepth = [](const Vec3& p, const Vec3& centre, const Vec3& half) {
        double depth = 1e9;
        for (int a = 0; a < 3; ++a) depth = std::min(depth, half[a] - std::abs(p[a] - centre[a]));
        return depth;
    };
    for (int z = 0; z < 11; ++z)
        for (int y = 0; y < 31; ++y)
            for (int x = 0; x < 31; ++x) {
                const Vec3 p{-0.3 + 0.02 * x, -0.3 + 0.02 * y, -0.1 + 0.02 * z};
                solid->depth.push_back(
                    float(std::max(boxDepth(p, {0.0, -0.1, 0.0}, {0.25, 0.06, 0.08}),
                                   boxDepth(p, {-0.18, 0.05, 0.0}, {0.06, 0.2, 0.08}))));
            }
    return solid;
}

}  // namespace modeflow::testing
