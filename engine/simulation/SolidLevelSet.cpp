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
        const std::array<int, 3> d{corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
        std::array<double, 3> w{}, slope{};  // the weights along each axis, their derivatives
        for (int a = 0; a < 3; ++a) {
            w[a] = d[a] ? f[a] : 1.0 - f[a];
            slope[a] = (d[a] ? 1.0 : -1.0) / set.spacing;
        }
        add(std::size_t(i[0] + d[0]) + std::size_t(set.samples[0]) *
                                           (std::size_t(i[1] + d[1]) +
                                            std::size_t(set.samples[1]) * std::size_t(i[2] + d[2])),
            w[0] * w[1] * w[2],
            Vec3{slope[0] * w[1] * w[2], w[0] * slope[1] * w[2], w[0] * w[1] * slope[2]});
    }
    return true;
}

}  // namespace

double SolidLevelSet::depthAt(const Vec3& p) const {
    double sum = 0.0;
    if (!trilinear(*this, p,
                   [&](std::size_t s, double w, const Vec3&) { sum += w * double(depth[s]); }))
        return -spacing;
    return sum;
}

double SolidLevelSet::depthAt(const Vec3& p, Vec3& gradient) const {
    double sum = 0.0;
    gradient = {0.0, 0.0, 0.0};
    const bool on = trilinear(*this, p, [&](std::size_t s, double w, const Vec3& dw) {
        sum += w * double(depth[s]);
        for (int a = 0; a < 3; ++a) gradient[a] += dw[a] * double(depth[s]);
    });
    return on ? sum : -spacing;
}

Vec3 SolidLevelSet::velocityAt(const Vec3& p) const {
    Vec3 sum{0.0, 0.0, 0.0};
    if (velocity.empty()) return sum;
    trilinear(*this, p, [&](std::size_t s, double w, const Vec3&) {
        for (int a = 0; a < 3; ++a) sum[a] += w * double(velocity[3 * s + std::size_t(a)]);
    });
    return sum;
}

}  // namespace modeflow
