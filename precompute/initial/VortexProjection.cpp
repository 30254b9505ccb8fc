/// @file VortexProjection.cpp
#include "precompute/initial/VortexProjection.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "engine/basis/VelocityBasis.h"
#include "engine/core/Error.h"
#include "engine/core/Vec3Math.h"
#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellDec.h"

namespace modeflow {
namespace {

/// The (Lamb–Oseen) core's share of a point vortex's velocity at displacement (dx, dy):
/// Γ/(2π) e^{−r²/σ²}/r² (−dy, dx), which the point vortex's field less it is.
Vec3 coreShare(const VortexSpec& v, double dx, double dy) {
    const double r2 = dx * dx + dy * dy, s2 = v.radius * v.radius;
    const double c = v.strength / (2.0 * std::numbers::pi) * std::exp(-r2 / s2) / r2;
    return {-c * dy, c * dx, 0.0};
}

Vec3 lambOseen(const VortexSpec& v, double dx, double dy) {
    const double r2 = dx * dx + dy * dy, s2 = v.radius * v.radius;
    // (1 − e^{−r²/σ²}) / r² → 1/σ² at the centre; expm1 keeps the small-r values accurate.
    const double shape = r2 < 1e-14 * s2 ? 1.0 / s2 : -std::expm1(-r2 / s2) / r2;
    const double c = v.strength / (2.0 * std::numbers::pi) * shape;
    return {-c * dy, c * dx, 0.0};
}

/// cot(w) − 1/w, by its series near 0 where the difference cancels, and through e^{2iw} with
/// |e^{2iw}| ≤ 1 elsewhere (cos/sin overflow far from the real axis).
std::complex<double> cotMinusInverse(std::complex<double> w) {
    if (std::abs(w) < 1e-2) return -w / 3.0 - w * w * w / 45.0;
    const std::complex<double> i(0.0, 1.0);
    const double side = w.imag() < 0.0 ? -1.0 : 1.0;  // cot is odd
    const std::complex<double> e = std::exp(2.0 * i * side * w);
    return side * i * (e + 1.0) / (e - 1.0) - 1.0 / w;
}

/// Σ_m 1/(z − m L) − 1/z: a row of point vortices along x with period L, less the one at 0
/// (Σ_m 1/(z − mL) = (π/L) cot(πz/L)).
std::complex<double> rowLessCentre(std::complex<double> z, double period) {
    const double k = std::numbers::pi / period;
    return k * cotMinusInverse(k * z);
}

/// x − c along `axis` moved to its nearest periodic image: within half a period.
double nearestImage(const GridSpec& grid, int axis, double d) {
    if (!grid.isPeriodic(axis)) return d;
    const double period = grid.boundsMax[axis] - grid.boundsMin[axis];
    return d - period * std::round(d / period);
}

/// A Lamb–Oseen vortex with its periodic images (2D): the point vortices' sum in closed form
/// (rows of cotangents; rows across a second periodic axis in pairs ±n, whose uniform far fields
/// cancel), less the cores of every image, which fall off as Gaussians; on a torus, the flow of
/// the vortex in a neutralizing background (below). With no periodic axis,
/// the vortex alone. The sum depends on x − c modulo the periods only, so a vortex on a seam is
/// the same vortex as one in the middle.
Vec3 periodicLambOseen(const VortexSpec& v, const GridSpec& grid, const Vec3& x) {
    const double dx = nearestImage(grid, 0, x[0] - v.center[0]);
    const double dy = nearestImage(grid, 1, x[1] - v.center[1]);
    Vec3 u = lambOseen(v, dx, dy);
    const bool px = grid.isPeriodic(0), py = grid.isPeriodic(1);
    if (!px && !py) return u;
    const double lx = grid.boundsMax[0] - grid.boundsMin[0];
    const double ly = grid.boundsMax[1] - grid.boundsMin[1];
    // S − 1/z, S = Σ over the images of 1/(z − image): the velocity is Γ/(2πi) S as u − iv.
    using C = std::complex<double>;
    const C z(dx, dy), i(0.0, 1.0);
    C sum;
    if (px) {
        sum = rowLessCentre(z, lx);
        if (py) {
            // Rows n and −n together: their far fields ±i π/Lx cancel, the rest falls off as
            // e^{−2π |n| Ly / Lx}; enough rows for that to reach 1e-16.
            const int rows = int(std::ceil(36.0 * lx / (2.0 * std::numbers::pi * ly) + 0.5));
            for (int n = 1; n <= rows; ++n)
                for (const double s : {1.0, -1.0}) {
                    const C row = z - s * double(n) * ly * i;
                    sum += rowLessCentre(row, lx) + 1.0 / row;
                }
        }
    } else {
        // A column along y: 1/(z − i m L) = −i / (z' − m L) with z' = −i z.
        sum = -i * rowLessCentre(-i * z, ly);
    }
    const C w = v.strength / (2.0 * std::numbers::pi * i) * sum;
    u[0] += w.real();
    u[1] -= w.imag();
    // On a torus a vortex comes with a uniform vorticity −Γ/|box| (circulation cannot but sum to
    // zero there): the shear Γ y'/|box| joins the rows' field across y' = ±Ly/2, and makes the
    // whole the periodic flow of the vortex's vorticity with zero mean (u = ∇⊥ψ, −Δψ = ω − ω̄).
    // For vortices whose circulations sum to zero the backgrounds cancel.
    if (px && py) u[0] += v.strength * dy / (lx * ly);
    // The images' cores: every image within six core radii of x (the nearest is in lambOseen).
    const auto reach = [&](bool periodic, double period) {
        return periodic ? int(std::ceil(6.0 * v.radius / period)) + 1 : 0;
    };
    const int mx = reach(px, lx), my = reach(py, ly);
    for (int a = -mx; a <= mx; ++a)
        for (int b = -my; b <= my; ++b) {
            if (a == 0 && b == 0) continue;
            const Vec3 core = coreShare(v, dx + a * lx, dy + b * ly);
            u[0] -= core[0];
            u[1] -= core[1];
        }
    return u;
}

/// A vortex ring by Biot–Savart over its chords; along periodic axes each chord acts through
/// its image nearest x (the ring's far field falls off as a dipole's, 1/r³), so the field too
/// depends on x − c modulo the periods only.
Vec3 ring(const VortexSpec& v, const GridSpec& grid, const Vec3& x) {
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
        Vec3 r;
        for (int k = 0; k < 3; ++k) r[k] = nearestImage(grid, k, x[k] - 0.5 * (a[k] + b[k]));
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

Vec3 vortexVelocity(std::span<const VortexSpec> vortices, const GridSpec& grid, const Vec3& x) {
    Vec3 u{0.0, 0.0, 0.0};
    for (const VortexSpec& v : vortices) {
        const Vec3 d = grid.dim == 2 ? periodicLambOseen(v, grid, x) : ring(v, grid, x);
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
    const Eigen::VectorXd flux =
        faceFluxes(cache, [&](const Vec3& x) { return vortexVelocity(vortices, cache.grid, x); });
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
