#include "engine/simulation/SolidLevelSet.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace modeflow {
namespace {

/// Calls add(sample index, weight) for the eight samples around `p`; false (and no call) outside
/// the lattice.
template <typename Add>
bool trilinear(const SolidLevelSet& set, const Vec3& p, Add&& add) {
    std::array<int, 3> i{};
    std::array<double, 3> f{};
    for (int a = 0; a < 3; ++a) {
        const double x = (p[a] - set.origin[a]) / set.spacing;
        // The last sample pair's cell holds x = samples − 1 too.
        if (!(x >= 0.0) || x > double(set.samples[a] - 1)) return false;
        i[a] = std::min(int(x), set.samples[a] - 2);
        f[a] = x - i[a];
    }
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
        const double w =
            (dx ? f[0] : 1.0 - f[0]) * (dy ? f[1] : 1.0 - f[1]) * (dz ? f[2] : 1.0 - f[2]);
        add(std::size_t(i[0] + dx) +
                std::size_t(set.samples[0]) *
                    (std::size_t(i[1] + dy) + std::size_t(set.samples[1]) * std::size_t(i[2] + dz)),
            w);
    }
    return true;
}

}  // namespace

double SolidLevelSet::depthAt(const Vec3& p) const {
    double sum = 0.0;
    if (!trilinear(*this, p, [&](std::size_t s, double w) { sum += w * double(depth[s]); }))
        return -spacing;
    return sum;
}

Vec3 SolidLevelSet::velocityAt(const Vec3& p) const {
    Vec3 sum{0.0, 0.0, 0.0};
    if (velocity.empty()) return sum;
    trilinear(*this, p, [&](std::size_t s, double w) {
        for (int a = 0; a < 3; ++a) sum[a] += w * double(velocity[3 * s + std::size_t(a)]);
    });
    return sum;
}

}  // namespace modeflow
