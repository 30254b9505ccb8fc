/// @file VortexProjection.cpp
#include "precompute/initial/VortexProjection.h"

#include <cmath>
#include <numbers>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/Vec3Math.h"
#include "engine/format/VelocityBasis.h"
#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellDec.h"

namespace modeflow {
namespace {

Vec3 lambOseen(const VortexSpec& v, const Vec3& x) {
    const double dx = x[0] - v.center[0], dy = x[1] - v.center[1];
    const double r2 = dx * dx + dy * dy, s2 = v.radius * v.radius;
    // (1 − e^{−r²/σ²}) / r² → 1/σ² at the centre; expm1 keeps the small-r values accurate.
    const double shape = r2 < 1e-14 * s2 ? 1.0 / s2 : -std::expm1(-r2 / s2) / r2;
    const double c = v.strength / (2.0 * std::numbers::pi) * shape;
    return {-c * dy, c * dx, 0.0};
}

Vec3 ring(const VortexSpec& v, const Vec3& x) {
    const double nn = norm(v.normal);
    const Vec3 n{v.normal[0] / nn, v.normal[1] / nn, v.normal[2] / nn};
    // e1, e2 span the ring's plane with e1 × e2 = n, so θ increasing turns right-handedly.
    const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    Vec3 e1 = cross(helper, n);
    const double l1 = norm(e1);
    for (double& c : e1) c /= l1;
    const Vec3 e2 = cross(n, e1);
    auto point = [&](double theta) {
        const double c = std::cos(theta), s = std::sin(theta);
        return Vec3{v.center[0] + v.ringRadius * (c * e1[0] + s * e2[0]),
                    v.center[1] + v.ringRadius * (c * e1[1] + s * e2[1]),
                    v.center[2] + v.ringRadius * (c * e1[2] + s * e2[2])};
    };
    const double s2 = v.radius * v.radius;
    const double dTheta = 2.0 * std::numbers::pi / kRingSegments;
    Vec3 u{0.0, 0.0, 0.0};
    Vec3 a = point(0.0);
    for (int j = 0; j < kRingSegments; ++j) {
        const Vec3 b = point((j + 1) * dTheta);
        const Vec3 dl{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const Vec3 r{x[0] - 0.5 * (a[0] + b[0]), x[1] - 0.5 * (a[1] + b[1]),
                     x[2] - 0.5 * (a[2] + b[2])};
        const double d2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + s2;
        const double w = 1.0 / (d2 * std::sqrt(d2));
        const Vec3 c = cross(dl, r);
        for (int k = 0; k < 3; ++k) u[k] += w * c[k];
        a = b;
    }
    const double scale = v.strength / (4.0 * std::numbers::pi);
    return {scale * u[0], scale * u[1], scale * u[2]};
}

}  // namespace

Vec3 vortexVelocity(std::span<const VortexSpec> vortices, int dim, const Vec3& x) {
    Vec3 u{0.0, 0.0, 0.0};
    for (const VortexSpec& v : vortices) {
        const Vec3 d = dim == 2 ? lambOseen(v, x) : ring(v, x);
        for (int k = 0; k < 3; ++k) u[k] += d[k];
    }
    return u;
}

Eigen::VectorXd faceFluxes(const BasisCache& cache, const VelocityField& u) {
    const GridSpec& grid = cache.grid;
    const int n = grid.dim;
    const CubicalComplex cx(grid);
    // 2-point Gauss–Legendre on [0, 1]: exact for cubics along each tangential axis.
    const double g = 0.5 / std::sqrt(3.0);
    const double nodes[2] = {0.5 - g, 0.5 + g};
    const int points = n == 2 ? 2 : 4;

    Eigen::VectorXd flux(static_cast<Eigen::Index>(cache.faces.size()));
    for (std::size_t f = 0; f < cache.faces.size(); ++f) {
        const Element e = cx.element(n - 1, cache.faces[f]);
        int normal = 0;
        int tangent[2] = {-1, -1};
        int t = 0;
        for (int a = 0; a < n; ++a) {
            if ((e.axes >> a) & 1u)
                tangent[t++] = a;
            else
                normal = a;
        }
        Vec3 corner{0.0, 0.0, 0.0};
        for (int a = 0; a < n; ++a) corner[a] = grid.boundsMin[a] + e.pos[a] * grid.spacing(a);
        double mean = 0.0;
        for (int q = 0; q < points; ++q) {
            Vec3 x = corner;
            x[tangent[0]] += nodes[q & 1] * grid.spacing(tangent[0]);
            if (n == 3) x[tangent[1]] += nodes[q >> 1] * grid.spacing(tangent[1]);
            mean += u(x)[normal];
        }
        mean /= points;
        const auto i = static_cast<Eigen::Index>(f);
        flux[i] = mean * dualMeasure(grid, e) / cache.faceStar[i];
    }
    return flux;
}

Eigen::VectorXd projectFluxes(const BasisCache& cache, const Eigen::VectorXd& fluxes) {
    const VelocityBasis basis(cache);
    if (fluxes.size() != basis.dofCount() || cache.faceStar.size() != basis.dofCount()) {
        throw Error("projection: " + std::to_string(fluxes.size()) +
                    " face fluxes for a basis on " + std::to_string(basis.dofCount()) + " faces");
    }
    return basis.transposed(cache.faceStar.cwiseProduct(fluxes));
}

Eigen::VectorXd projectVortices(const BasisCache& cache, std::span<const VortexSpec> vortices,
                                double energy) {
    if (vortices.empty()) {
        throw Error("[initial].vortex: velocity = \"vortices\" needs at least one vortex");
    }
    const int dim = cache.grid.dim;
    const Eigen::VectorXd flux =
        faceFluxes(cache, [&](const Vec3& x) { return vortexVelocity(vortices, dim, x); });
    Eigen::VectorXd v = projectFluxes(cache, flux);
    if (energy > 0.0) {
        // |v| by stableNorm: huge strengths would overflow ½|v|² and rescale to 0.
        const double norm = v.stableNorm();
        if (norm == 0.0) {
            throw Error(
                "[initial].energy: the vortices project to a zero state on this basis "
                "(outside the domain, or all strengths 0), so it cannot be rescaled to " +
                std::to_string(energy));
        }
        v *= std::sqrt(2.0 * energy) / norm;
    }
    return v;
}

}  // namespace modeflow
