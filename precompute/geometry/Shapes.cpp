/// @file Shapes.cpp
/// Analytic shapes and makeShape. Exact signed distances everywhere (the ellipsoid's through
/// a root search after Eberly), with the sign decided by the shape's own implicit equation so that
/// inside/outside is exact and points exactly on the surface give exactly 0.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "engine/core/Error.h"
#include "precompute/geometry/ImplicitShape.h"
#include "precompute/geometry/MeshLevelSet.h"

namespace modeflow {
namespace {

std::string number(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

void requirePositive(double x, const char* key) {
    if (!(x > 0.0) || !std::isfinite(x))
        throw Error(std::string(key) + " must be a positive number (got " + number(x) + ")");
}

void requireFinite(const Vec3& v, int dim, const char* key) {
    for (int i = 0; i < dim; ++i)
        if (!std::isfinite(v[i]))
            throw Error(std::string(key) + " must hold finite numbers (entry " +
                        std::to_string(i + 1) + " is " + number(v[i]) + ")");
}

/// Plain Euclidean norms: std::hypot guards against overflow beyond 1e154, which no scene reaches,
/// and costs several times more.
double length(double a, double b) {
    return std::sqrt(a * a + b * b);
}
double length(double a, double b, double c) {
    return std::sqrt(a * a + b * b + c * c);
}

class Ball final : public ImplicitShape {
public:
    Ball(const Vec3& center, double radius, int dim)
        : mCenter(center), mRadius(radius), mDim(dim) {}
    double value(const Vec3& p) const override {
        const double dx = p[0] - mCenter[0];
        const double dy = p[1] - mCenter[1];
        const double dz = mDim == 3 ? p[2] - mCenter[2] : 0.0;
        return mRadius - std::sqrt(dx * dx + dy * dy + dz * dz);
    }

private:
    Vec3 mCenter;
    double mRadius;
    int mDim;
};

class Box final : public ImplicitShape {
public:
    Box(const Vec3& min, const Vec3& max, int dim) : mMin(min), mMax(max), mDim(dim) {}
    double value(const Vec3& p) const override {
        // Per-axis signed slab distance written with the corners themselves (not centre ± half
        // width) so that a point on a face gives exactly 0.
        double outside2 = 0.0;
        double inside = -std::numeric_limits<double>::infinity();
        for (int i = 0; i < mDim; ++i) {
            const double q = std::max(mMin[i] - p[i], p[i] - mMax[i]);
            if (q > 0.0) outside2 += q * q;
            inside = std::max(inside, q);
        }
        return outside2 > 0.0 ? -std::sqrt(outside2) : 0.0 - inside;  // +0 on a face, not -0
    }

private:
    Vec3 mMin;
    Vec3 mMax;
    int mDim;
};

/// Distance from a point to an ellipse or ellipsoid, after Eberly, "Distance from a point to an
/// ellipse, an ellipsoid, or a hyperellipsoid" (2013). Semi-axes e[0] >= ... >= e[n-1] > 0, query
/// y >= 0 (first quadrant/octant). The nearest point is x_i = e_i² y_i / (t + e_i²) with t the
/// root of Σ (x_i/e_i)² = 1. Eberly bisects on s = t/e_{n-1}²; here the unknown is
/// u = s + 1 = t/e_{n-1}² + 1 instead, so every denominator u + c_i (c_i = e_i²/e_{n-1}² - 1 >= 0)
/// is a sum of non-negative numbers: no cancellation, full relative precision even when the
/// root sits at u ≈ 1e-300 (points near the centre of a near-round ellipse, or near a symmetry
/// plane). Eberly's s-form gives infinities or errors of 1e-6 there.
constexpr int kMaxRootIterations = 400;  // safeguarded Newton: ~6 in practice, ~80 worst case

/// All z_i = y_i/e_i > 0. g = Σ z_i² - 1 (the sign says inside/outside).
double distanceGeneric(int n, const double* e, const double* y, const double* z, double g) {
    const double eLast = e[n - 1];
    std::array<double, 3> c{}, num{};
    for (int i = 0; i < n; ++i) {
        c[i] = (e[i] - eLast) * ((e[i] + eLast) / (eLast * eLast));
        num[i] = (1.0 + c[i]) * z[i];
    }
    // G(u) = Σ (num_i / (u + c_i))² - 1 is decreasing on u > 0. G(z_last) >= 0 (its last term is
    // 1); G(1) = g < 0 inside; outside, every term at u = |num| is at most (num_i/|num|)².
    double lo = z[n - 1];
    double hi = 1.0;
    if (g > 0.0) {
        hi = n == 2 ? length(num[0], num[1]) : length(num[0], num[1], num[2]);
    }
    // Newton on H(u) = S(u)^(-1/2) - 1, S = G + 1: exactly linear for one term and concave in
    // general, so steps from the left of the root stay left and converge fast (~6 iterations).
    // The bracket keeps it safe: a step that leaves it (or an overflowed S) is replaced by a
    // geometric or arithmetic midpoint.
    double u = lo;
    for (int it = 0; it < kMaxRootIterations; ++it) {
        double S = 0.0, T = 0.0;
        for (int i = 0; i < n; ++i) {
            const double w = 1.0 / (u + c[i]);
            const double r2 = num[i] * w * num[i] * w;
            S += r2;
            T += r2 * w;
        }
        if (S > 1.0)
            lo = u;
        else if (S < 1.0)
            hi = u;
        else
            break;
        const double step = S * (std::sqrt(S) - 1.0) / T;  // -H/H'
        if (std::abs(step) <= 4.0 * std::numeric_limits<double>::epsilon() * u) break;
        double next = u + step;
        if (!(next > lo && next < hi))
            next = hi > 4.0 * lo ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) break;  // the bracket holds two neighbouring doubles
        u = next;
    }
    // x_i - y_i = y_i (1 - u) / (u + c_i): no cancellation between x and y.
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double w = y[i] / (u + c[i]);
        sum += w * w;
    }
    return std::abs(1.0 - u) * std::sqrt(sum);
}

/// e0 >= e1 > 0, y0, y1 >= 0.
double distanceToEllipse(double e0, double e1, double y0, double y1) {
    const double z0 = y0 / e0;
    const double z1 = y1 / e1;
    if (z1 > 0.0) {
        if (z0 > 0.0) {
            const double g = z0 * z0 + z1 * z1 - 1.0;
            if (g == 0.0) return 0.0;
            const double e[2] = {e0, e1}, y[2] = {y0, y1}, z[2] = {z0, z1};
            return distanceGeneric(2, e, y, z, g);
        }
        return std::abs(y1 - e1);  // on the minor axis the nearest point is its end
    }
    // On the major axis: the nearest point leaves the axis while e0 y0 < e0² - e1².
    const double numer0 = e0 * y0;
    const double denom0 = (e0 - e1) * (e0 + e1);
    if (numer0 < denom0) {
        const double xde0 = numer0 / denom0;
        return length(e0 * xde0 - y0, e1 * std::sqrt(std::max(0.0, 1.0 - xde0 * xde0)));
    }
    return std::abs(y0 - e0);
}

/// e0 >= e1 >= e2 > 0, y >= 0.
double distanceToEllipsoid(double e0, double e1, double e2, double y0, double y1, double y2) {
    const double z0 = y0 / e0;
    const double z1 = y1 / e1;
    const double z2 = y2 / e2;
    if (z2 > 0.0) {
        if (z1 > 0.0) {
            if (z0 > 0.0) {
                const double g = z0 * z0 + z1 * z1 + z2 * z2 - 1.0;
                if (g == 0.0) return 0.0;
                const double e[3] = {e0, e1, e2}, y[3] = {y0, y1, y2}, z[3] = {z0, z1, z2};
                return distanceGeneric(3, e, y, z, g);
            }
            return distanceToEllipse(e1, e2, y1, y2);
        }
        if (z0 > 0.0) return distanceToEllipse(e0, e2, y0, y2);
        return std::abs(y2 - e2);
    }
    // In the plane of the two larger axes: the nearest point may leave it.
    const double denom0 = (e0 - e2) * (e0 + e2);
    const double denom1 = (e1 - e2) * (e1 + e2);
    const double numer0 = e0 * y0;
    const double numer1 = e1 * y1;
    if (numer0 < denom0 && numer1 < denom1) {
        const double xde0 = numer0 / denom0;
        const double xde1 = numer1 / denom1;
        const double discr = 1.0 - xde0 * xde0 - xde1 * xde1;
        if (discr > 0.0) return length(e0 * xde0 - y0, e1 * xde1 - y1, e2 * std::sqrt(discr));
    }
    return distanceToEllipse(e0, e1, y0, y1);
}

class Ellipsoid final : public ImplicitShape {
public:
    Ellipsoid(const Vec3& center, const Vec3& radii, int dim)
        : mCenter(center), mRadii(radii), mDim(dim) {
        // Eberly's algorithm wants the semi-axes in decreasing order.
        for (int i = 0; i < 3; ++i) mOrder[i] = i;
        std::stable_sort(mOrder.begin(), mOrder.begin() + dim,
                         [&](int a, int b) { return radii[a] > radii[b]; });
    }

    double value(const Vec3& p) const override {
        Vec3 y{};
        double q = -1.0;
        for (int i = 0; i < mDim; ++i) {
            y[i] = std::abs(p[i] - mCenter[i]);
            const double z = y[i] / mRadii[i];
            q += z * z;
        }
        // The implicit equation decides the sign (and the exact zero set); the magnitude is the
        // true distance to the surface.
        if (q == 0.0) return 0.0;
        const Vec3& e = mRadii;
        const auto& o = mOrder;
        const double d =
            mDim == 2 ? distanceToEllipse(e[o[0]], e[o[1]], y[o[0]], y[o[1]])
                      : distanceToEllipsoid(e[o[0]], e[o[1]], e[o[2]], y[o[0]], y[o[1]], y[o[2]]);
        return q < 0.0 ? d : -d;
    }

private:
    Vec3 mCenter;
    Vec3 mRadii;
    std::array<int, 3> mOrder{};
    int mDim;
};

/// Finite solid cylinder, axis z, between center.z ± halfHeight.
class Cylinder final : public ImplicitShape {
public:
    Cylinder(const Vec3& center, double radius, double halfHeight)
        : mCenter(center), mRadius(radius), mHalfHeight(halfHeight) {}
    double value(const Vec3& p) const override {
        const double dr = length(p[0] - mCenter[0], p[1] - mCenter[1]) - mRadius;
        const double dz = std::abs(p[2] - mCenter[2]) - mHalfHeight;
        const double outside = length(std::max(dr, 0.0), std::max(dz, 0.0));
        return 0.0 - (std::min(std::max(dr, dz), 0.0) + outside);
    }

private:
    Vec3 mCenter;
    double mRadius;
    double mHalfHeight;
};

/// Solid torus around the z axis through center: the points within minorRadius of the circle of
/// majorRadius in the plane z = center.z.
class Torus final : public ImplicitShape {
public:
    Torus(const Vec3& center, double majorRadius, double minorRadius)
        : mCenter(center), mMajor(majorRadius), mMinor(minorRadius) {}
    double value(const Vec3& p) const override {
        const double radial = length(p[0] - mCenter[0], p[1] - mCenter[1]) - mMajor;
        return mMinor - length(radial, p[2] - mCenter[2]);
    }

private:
    Vec3 mCenter;
    double mMajor;
    double mMinor;
};

}  // namespace

std::unique_ptr<ImplicitShape> makeShape(const ShapeSpec& spec, int dim, double voxelSize) {
    if (dim != 2 && dim != 3)
        throw Error("shapes exist in 2D or 3D only (got dimension " + std::to_string(dim) + ")");
    switch (spec.kind) {
        case ShapeKind::Ball:
            requireFinite(spec.center, dim, "center");
            requirePositive(spec.radius, "radius");
            return std::make_unique<Ball>(spec.center, spec.radius, dim);
        case ShapeKind::Box:
            requireFinite(spec.min, dim, "min");
            requireFinite(spec.max, dim, "max");
            for (int i = 0; i < dim; ++i)
                if (!(spec.max[i] > spec.min[i]))
                    throw Error("max must exceed min on every axis (axis " + std::to_string(i + 1) +
                                ": min " + number(spec.min[i]) + ", max " + number(spec.max[i]) +
                                ")");
            return std::make_unique<Box>(spec.min, spec.max, dim);
        case ShapeKind::Ellipsoid:
            requireFinite(spec.center, dim, "center");
            for (int i = 0; i < dim; ++i) requirePositive(spec.radii[i], "every entry of radii");
            return std::make_unique<Ellipsoid>(spec.center, spec.radii, dim);
        case ShapeKind::Cylinder:
            if (dim != 3) throw Error("cylinder exists only in 3D (axis z); in 2D use a box");
            requireFinite(spec.center, dim, "center");
            requirePositive(spec.radius, "radius");
            requirePositive(spec.halfHeight, "half_height");
            return std::make_unique<Cylinder>(spec.center, spec.radius, spec.halfHeight);
        case ShapeKind::Torus:
            if (dim != 3)
                throw Error("torus exists only in 3D (axis z); in 2D use a ball minus a ball");
            requireFinite(spec.center, dim, "center");
            requirePositive(spec.majorRadius, "major_radius");
            requirePositive(spec.minorRadius, "minor_radius");
            return std::make_unique<Torus>(spec.center, spec.majorRadius, spec.minorRadius);
        case ShapeKind::Mesh:
            if (dim != 3) throw Error("mesh exists only in 3D scenes");
            return loadMeshShape(spec.meshFile, voxelSize);
    }
    throw Error("unknown shape kind");
}

}  // namespace modeflow
