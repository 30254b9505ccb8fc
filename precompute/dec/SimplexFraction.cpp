#include "precompute/dec/SimplexFraction.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Dense>

namespace modeflow {
namespace {

// Fraction of the simplex near the single positive vertex p (all others q_j <= 0):
// p^k / Π (p - q_j). Denominators are sums of magnitudes, so no cancellation.
double cornerFraction(double p, std::span<const double> others) {
    double r = 1.0;
    for (double q : others) r *= p / (p - q);
    return r;
}

// Tetrahedron with two positive vertices a, b and two non-positive c, d: the positive part is a
// prism with triangles (A, Pac, Pad) and (B, Pbc, Pbd), split into three tetrahedra whose volumes
// are barycentric determinants.
double twoTwoFraction(double a, double b, double c, double d) {
    using Bary = Eigen::Vector4d;
    auto cut = [](int i, double fi, int j, double fj) {
        const double s = fi / (fi - fj);  // from vertex i towards j
        Bary p = Bary::Zero();
        p[i] = 1.0 - s;
        p[j] = s;
        return p;
    };
    const Bary A = Bary::Unit(0), B = Bary::Unit(1);
    const Bary pac = cut(0, a, 2, c), pad = cut(0, a, 3, d);
    const Bary pbc = cut(1, b, 2, c), pbd = cut(1, b, 3, d);
    auto volume = [](const Bary& p, const Bary& q, const Bary& r, const Bary& s) {
        Eigen::Matrix4d m;
        m << p, q, r, s;
        return std::abs(m.determinant());
    };
    // Prism (a0,a1,a2)=(A,pac,pad), (b0,b1,b2)=(B,pbc,pbd).
    return volume(A, pac, pad, pbd) + volume(A, pac, pbc, pbd) + volume(A, B, pbc, pbd);
}

}  // namespace

double positiveFraction(std::span<const double> values) {
    std::array<double, 4> pos{}, neg{};
    int np = 0, nn = 0;
    for (double v : values) (v > 0.0 ? pos[np++] : neg[nn++]) = v;
    if (np == 0) return 0.0;
    if (nn == 0) return 1.0;
    if (np == 1) return cornerFraction(pos[0], std::span(neg.data(), nn));
    if (nn == 1) {
        // Complement: the single non-positive corner, with signs flipped.
        std::array<double, 3> flipped{};
        for (int i = 0; i < np; ++i) flipped[i] = -pos[i];
        if (neg[0] == 0.0) return 1.0;
        return 1.0 - cornerFraction(-neg[0], std::span(flipped.data(), np));
    }
    return std::clamp(twoTwoFraction(pos[0], pos[1], neg[0], neg[1]), 0.0, 1.0);
}

}  // namespace modeflow
