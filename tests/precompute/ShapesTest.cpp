/// @file ShapesTest.cpp
/// Analytic shapes and the CSG domain: exact signs and zero sets, distances against brute force
/// over densely sampled surfaces, the 1-Lipschitz bound, and CSG order semantics.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/Error.h"
#include "precompute/geometry/Domain.h"
#include "precompute/geometry/ImplicitShape.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kVoxel = 0.01;  // unused by analytic shapes

using testing::ball;
using testing::box;
using testing::cylinder;
using testing::ellipsoid;
using testing::torus;

double value(const ShapeSpec& spec, int dim, const Vec3& p) {
    return makeShape(spec, dim, kVoxel)->value(p);
}

double norm(const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

/// A shape together with an independent description: the inside predicate from its defining
/// inequality and a dense sample of its surface, `spacing` = the largest distance from a surface
/// point to the nearest sample.
struct Reference {
    std::string name;
    ShapeSpec spec;
    int dim;
    std::function<bool(const Vec3&)> inside;
    std::vector<Vec3> surface;
    double spacing;
    Vec3 lo, hi;  ///< where to draw query points
};

std::vector<Reference> references() {
    std::vector<Reference> refs;
    const int n2 = 20000;
    {  // disk
        Reference r{"disk",     ball({0.3, -0.2, 0}, 0.7), 2, nullptr, {}, 0, {-1, -1.5, 0},
                    {1.5, 1, 0}};
        r.inside = [](const Vec3& p) { return std::hypot(p[0] - 0.3, p[1] + 0.2) < 0.7; };
        for (int i = 0; i < n2; ++i) {
            const double t = 2 * kPi * i / n2;
            r.surface.push_back({0.3 + 0.7 * std::cos(t), -0.2 + 0.7 * std::sin(t), 0});
        }
        r.spacing = 0.7 * kPi / n2;
        refs.push_back(r);
    }
    {  // rectangle
        Reference r{
            "rectangle",  box({-0.5, -0.25, 0}, {0.75, 0.5, 0}), 2, nullptr, {}, 0, {-1.2, -1, 0},
            {1.4, 1.2, 0}};
        r.inside = [](const Vec3& p) {
            return p[0] > -0.5 && p[0] < 0.75 && p[1] > -0.25 && p[1] < 0.5;
        };
        const double h = 1e-4;
        for (double x = -0.5; x <= 0.75; x += h) {
            r.surface.push_back({x, -0.25, 0});
            r.surface.push_back({x, 0.5, 0});
        }
        for (double y = -0.25; y <= 0.5; y += h) {
            r.surface.push_back({-0.5, y, 0});
            r.surface.push_back({0.75, y, 0});
        }
        r.spacing = h;
        refs.push_back(r);
    }
    {  // ellipse
        Reference r{"ellipse",
                    ellipsoid({0.1, 0.2, 0}, {0.9, 0.35, 0}),
                    2,
                    nullptr,
                    {},
                    0,
                    {-1.2, -0.6, 0},
                    {1.4, 1.0, 0}};
        r.inside = [](const Vec3& p) {
            const double x = (p[0] - 0.1) / 0.9, y = (p[1] - 0.2) / 0.35;
            return x * x + y * y < 1;
        };
        const int n = 40000;
        for (int i = 0; i < n; ++i) {
            const double t = 2 * kPi * i / n;
            r.surface.push_back({0.1 + 0.9 * std::cos(t), 0.2 + 0.35 * std::sin(t), 0});
        }
        r.spacing = 0.9 * kPi / n;
        refs.push_back(r);
    }
    const int nt = 300, np = 600;
    auto sampleAngles = [&](const std::function<Vec3(double, double)>& f) {
        std::vector<Vec3> pts;
        for (int i = 0; i <= nt; ++i)
            for (int j = 0; j < np; ++j) pts.push_back(f(kPi * i / nt, 2 * kPi * j / np));
        return pts;
    };
    {  // ball
        Reference r{
            "ball",       ball({0.1, 0.2, -0.3}, 0.6), 3, nullptr, {}, 0, {-0.8, -0.7, -1.2},
            {1, 1.1, 0.6}};
        r.inside = [](const Vec3& p) { return norm(p, {0.1, 0.2, -0.3}) < 0.6; };
        r.surface = sampleAngles([](double th, double ph) {
            return Vec3{0.1 + 0.6 * std::sin(th) * std::cos(ph),
                        0.2 + 0.6 * std::sin(th) * std::sin(ph), -0.3 + 0.6 * std::cos(th)};
        });
        r.spacing = 0.6 * (kPi / nt + 2 * kPi / np);
        refs.push_back(r);
    }
    {  // ellipsoid with three different radii, the largest along y
        Reference r{"ellipsoid",
                    ellipsoid({0, 0.1, 0.2}, {0.5, 0.8, 0.3}),
                    3,
                    nullptr,
                    {},
                    0,
                    {-0.9, -1.0, -0.4},
                    {0.9, 1.2, 0.8}};
        r.inside = [](const Vec3& p) {
            const double x = p[0] / 0.5, y = (p[1] - 0.1) / 0.8, z = (p[2] - 0.2) / 0.3;
            return x * x + y * y + z * z < 1;
        };
        r.surface = sampleAngles([](double th, double ph) {
            return Vec3{0.5 * std::sin(th) * std::cos(ph), 0.1 + 0.8 * std::sin(th) * std::sin(ph),
                        0.2 + 0.3 * std::cos(th)};
        });
        r.spacing = 0.8 * (kPi / nt + 2 * kPi / np);
        refs.push_back(r);
    }
    {  // box
        Reference r{"box",
                    box({-0.5, -0.25, -0.4}, {0.5, 0.25, 0.3}),
                    3,
                    nullptr,
                    {},
                    0,
                    {-0.9, -0.6, -0.8},
                    {0.9, 0.7, 0.7}};
        r.inside = [](const Vec3& p) {
            return p[0] > -0.5 && p[0] < 0.5 && p[1] > -0.25 && p[1] < 0.25 && p[2] > -0.4 &&
                   p[2] < 0.3;
        };
        const double h = 0.004;
        const Vec3 lo{-0.5, -0.25, -0.4}, hi{0.5, 0.25, 0.3};
        for (int axis = 0; axis < 3; ++axis) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (double a = lo[u]; a <= hi[u] + 1e-12; a += h)
                for (double b = lo[v]; b <= hi[v] + 1e-12; b += h)
                    for (double side : {lo[axis], hi[axis]}) {
                        Vec3 p;
                        p[axis] = side;
                        p[u] = a;
                        p[v] = b;
                        r.surface.push_back(p);
                    }
        }
        r.spacing = 2 * h;
        refs.push_back(r);
    }
    {  // cylinder
        Reference r{"cylinder",
                    cylinder({0.1, -0.1, 0.2}, 0.4, 0.5),
                    3,
                    nullptr,
                    {},
                    0,
                    {-0.6, -0.8, -0.6},
                    {0.8, 0.6, 1.0}};
        r.inside = [](const Vec3& p) {
            return std::hypot(p[0] - 0.1, p[1] + 0.1) < 0.4 && std::abs(p[2] - 0.2) < 0.5;
        };
        const int na = 800;
        const double hz = 0.004, hr = 0.004;
        for (int j = 0; j < na; ++j) {
            const double c = std::cos(2 * kPi * j / na), s = std::sin(2 * kPi * j / na);
            for (double z = -0.3; z <= 0.7 + 1e-12; z += hz)
                r.surface.push_back({0.1 + 0.4 * c, -0.1 + 0.4 * s, z});
            for (double rad = 0; rad <= 0.4 + 1e-12; rad += hr)
                for (double z : {-0.3, 0.7})
                    r.surface.push_back({0.1 + rad * c, -0.1 + rad * s, z});
        }
        r.spacing = 0.4 * 2 * kPi / na + hz + hr;
        refs.push_back(r);
    }
    {  // torus
        Reference r{"torus",    torus({0.05, 0, -0.1}, 0.6, 0.2), 3, nullptr, {}, 0, {-1, -1, -0.5},
                    {1, 1, 0.3}};
        r.inside = [](const Vec3& p) {
            return std::hypot(std::hypot(p[0] - 0.05, p[1]) - 0.6, p[2] + 0.1) < 0.2;
        };
        const int nu = 1200, nv = 300;
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
                const double rad = 0.6 + 0.2 * std::cos(v);
                r.surface.push_back(
                    {0.05 + rad * std::cos(u), rad * std::sin(u), -0.1 + 0.2 * std::sin(v)});
            }
        r.spacing = 0.8 * 2 * kPi / nu + 0.2 * 2 * kPi / nv;
        refs.push_back(r);
    }
    return refs;
}

Vec3 randomPoint(std::mt19937& rng, const Vec3& lo, const Vec3& hi, int dim) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Vec3 p{};
    for (int i = 0; i < 3; ++i) p[i] = lo[i] + (hi[i] - lo[i]) * u(rng);
    if (dim == 2) p[2] = 10.0 * (u(rng) - 0.5);  // 2D shapes must ignore z
    return p;
}

TEST(Shapes, ExactZerosOnSurfacePoints) {
    // Points whose coordinates make the defining equation hold exactly in floating point.
    EXPECT_EQ(value(ball({1, 2, 0}, 5), 2, {4, 6, 0}), 0.0);
    EXPECT_EQ(value(ball({1, 2, 0}, 5), 2, {4, 6, 123.0}), 0.0);  // z ignored in 2D
    EXPECT_EQ(value(ball({1, 2, 3}, 5), 3, {1, 5, 7}), 0.0);
    EXPECT_EQ(value(ball({1, 2, 3}, 5), 3, {1, 2, -2}), 0.0);

    const ShapeSpec b2 = box({-0.3, 0.1, 0}, {0.7, 0.9, 0});
    for (const Vec3& p : {Vec3{-0.3, 0.5, 0}, Vec3{0.7, 0.5, 7}, Vec3{0.2, 0.1, 0},
                          Vec3{0.2, 0.9, 0}, Vec3{0.7, 0.9, 0}}) {
        const double v = value(b2, 2, p);
        EXPECT_EQ(v, 0.0);
        EXPECT_FALSE(std::signbit(v)) << "faces give +0, not -0";
    }
    const ShapeSpec b3 = box({-0.3, 0.1, -1.1}, {0.7, 0.9, 0.2});
    for (const Vec3& p : {Vec3{0, 0.5, -1.1}, Vec3{0, 0.5, 0.2}, Vec3{-0.3, 0.9, 0.2}})
        EXPECT_EQ(value(b3, 3, p), 0.0);

    const ShapeSpec e2 = ellipsoid({0.5, -0.25, 0}, {0.75, 0.25, 0});
    EXPECT_EQ(value(e2, 2, {1.25, -0.25, 0}), 0.0);
    EXPECT_EQ(value(e2, 2, {0.5, 0.0, 0}), 0.0);
    EXPECT_EQ(value(e2, 2, {0.5, -0.5, 9}), 0.0);
    const ShapeSpec e3 = ellipsoid({0, 0, 0.5}, {0.5, 1.5, 0.25});
    EXPECT_EQ(value(e3, 3, {0.5, 0, 0.5}), 0.0);
    EXPECT_EQ(value(e3, 3, {0, -1.5, 0.5}), 0.0);
    EXPECT_EQ(value(e3, 3, {0, 0, 0.75}), 0.0);

    const ShapeSpec c = cylinder({0, 0, 1}, 0.5, 0.25);
    EXPECT_EQ(value(c, 3, {0.5, 0, 1.1}), 0.0);
    EXPECT_EQ(value(c, 3, {0, -0.5, 0.75}), 0.0);
    EXPECT_EQ(value(c, 3, {0.1, 0.2, 1.25}), 0.0);
    EXPECT_EQ(value(c, 3, {0.1, 0.2, 0.75}), 0.0);

    const ShapeSpec t = torus({0, 0, 0.5}, 1.0, 0.25);
    EXPECT_EQ(value(t, 3, {1.25, 0, 0.5}), 0.0);
    EXPECT_EQ(value(t, 3, {0, -0.75, 0.5}), 0.0);
    EXPECT_EQ(value(t, 3, {1.0, 0, 0.75}), 0.0);
    EXPECT_EQ(value(t, 3, {0, 1.0, 0.25}), 0.0);
}

TEST(Shapes, KnownDistances) {
    EXPECT_DOUBLE_EQ(value(ball({1, 2, 0}, 5), 2, {1, 2, 0}), 5.0);
    EXPECT_DOUBLE_EQ(value(ball({1, 2, 0}, 5), 2, {1, 9, 0}), -2.0);
    EXPECT_DOUBLE_EQ(value(ball({0, 0, 0}, 1), 3, {0, 0, 3}), -2.0);
    EXPECT_DOUBLE_EQ(value(ball({0, 0, 0}, 1), 2, {0, 0, 3}), 1.0);  // 2D: z is no coordinate

    const ShapeSpec b = box({0, 0, 0}, {2, 1, 4});
    EXPECT_DOUBLE_EQ(value(b, 3, {1, 0.5, 2}), 0.5);
    EXPECT_NEAR(value(b, 3, {1.9, 0.5, 2}), 0.1, 1e-15);
    EXPECT_DOUBLE_EQ(value(b, 3, {3, 2, 2}), -std::sqrt(2.0));        // edge region
    EXPECT_DOUBLE_EQ(value(b, 3, {3, 3, 6}), -3.0);                   // corner region
    EXPECT_DOUBLE_EQ(value(b, 2, {3, 3, 6}), -std::sqrt(1.0 + 4.0));  // rectangle corner

    const ShapeSpec e = ellipsoid({0, 0, 0}, {2, 1, 0.5});
    EXPECT_DOUBLE_EQ(value(e, 3, {0, 0, 0}), 0.5);
    EXPECT_DOUBLE_EQ(value(e, 2, {0, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(value(e, 3, {3, 0, 0}), -1.0);
    EXPECT_DOUBLE_EQ(value(e, 3, {0, -3, 0}), -2.0);
    // Inside on the major axis the nearest point leaves the axis: (1.6, 0, 0.3), normal ∝ (1, 3).
    EXPECT_NEAR(value(e, 3, {1.5, 0, 0}), std::sqrt(0.1), 1e-15);

    const ShapeSpec c = cylinder({0, 0, 0}, 1, 2);
    EXPECT_DOUBLE_EQ(value(c, 3, {0, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(value(c, 3, {0, 0, 1.5}), 0.5);
    EXPECT_DOUBLE_EQ(value(c, 3, {0, 0, 5}), -3.0);
    EXPECT_DOUBLE_EQ(value(c, 3, {4, 0, 6}), -5.0);  // rim region: (3, 4) to the rim

    const ShapeSpec t = torus({0, 0, 0}, 1, 0.25);
    EXPECT_DOUBLE_EQ(value(t, 3, {1, 0, 0}), 0.25);
    EXPECT_DOUBLE_EQ(value(t, 3, {0, 0, 0}), -0.75);
    EXPECT_DOUBLE_EQ(value(t, 3, {0, 0, 1}), 0.25 - std::sqrt(2.0));
}

/// Every shape against brute force: the sign matches the defining inequality, |value| never
/// exceeds the distance to the surface, and (all analytic shapes are exact) falls short of it by
/// no more than the surface sampling error.
TEST(Shapes, SignsAndDistancesMatchBruteForce) {
    std::mt19937 rng(42);
    for (const Reference& ref : references()) {
        SCOPED_TRACE(ref.name);
        const auto shape = makeShape(ref.spec, ref.dim, kVoxel);
        int inside = 0, outside = 0;
        for (int k = 0; k < 300; ++k) {
            const Vec3 p = randomPoint(rng, ref.lo, ref.hi, ref.dim);
            const double v = shape->value(p);
            Vec3 q = p;
            if (ref.dim == 2) q[2] = 0.0;
            double brute = std::numeric_limits<double>::infinity();
            for (const Vec3& s : ref.surface) brute = std::min(brute, norm(q, s));
            if (brute > 1e-9) {
                EXPECT_EQ(v > 0, ref.inside(q)) << "at " << p[0] << ", " << p[1] << ", " << p[2];
                (v > 0 ? inside : outside)++;
            }
            EXPECT_LE(std::abs(v), brute * (1 + 1e-12) + 1e-14);
            EXPECT_GE(std::abs(v), brute - ref.spacing);
        }
        EXPECT_GT(inside, 20);
        EXPECT_GT(outside, 20);
        // Surface samples: the zero set (up to the rounding of the parametrization).
        for (std::size_t i = 0; i < ref.surface.size(); i += 97)
            EXPECT_NEAR(shape->value(ref.surface[i]), 0.0, 1e-14);
    }
}

TEST(Shapes, LipschitzOnRandomPairs) {
    std::mt19937 rng(7);
    std::normal_distribution<double> gauss(0.0, 1.0);
    for (const Reference& ref : references()) {
        SCOPED_TRACE(ref.name);
        const auto shape = makeShape(ref.spec, ref.dim, kVoxel);
        for (double scale : {1e-4, 1e-2, 0.3, 3.0}) {
            for (int k = 0; k < 4000; ++k) {
                const Vec3 a = randomPoint(rng, ref.lo, ref.hi, ref.dim);
                Vec3 b = a;
                for (int i = 0; i < ref.dim; ++i) b[i] += scale * gauss(rng);
                const double fa = shape->value(a), fb = shape->value(b);
                ASSERT_LE(std::abs(fa - fb), norm(a, b) * (1 + 1e-12))
                    << "a = " << a[0] << ", " << a[1] << ", " << a[2] << "; b = " << b[0] << ", "
                    << b[1] << ", " << b[2];
            }
        }
    }
}

TEST(Shapes, EllipsoidAxesAndDegenerateCases) {
    // Points on the symmetry planes and axes take Eberly's special branches.
    const ShapeSpec e = ellipsoid({0, 0, 0}, {1.0, 0.6, 0.3});
    const double x0 = 0.5 / (1 - 0.09);  // Eberly's closed form on the major axis
    EXPECT_NEAR(value(e, 3, {0.5, 0, 0}), std::hypot(x0 - 0.5, 0.3 * std::sqrt(1 - x0 * x0)),
                1e-15);
    EXPECT_NEAR(value(e, 3, {0, 0, 0.1}), 0.2, 1e-15);
    EXPECT_NEAR(value(e, 3, {0, 0, -0.5}), -0.2, 1e-15);
    EXPECT_NEAR(value(e, 3, {0, 0.9, 0}), -0.3, 1e-15);
    // Equal radii: the ellipsoid is a ball.
    const ShapeSpec sphere = ellipsoid({0.1, 0, 0}, {0.5, 0.5, 0.5});
    std::mt19937 rng(3);
    for (int k = 0; k < 1000; ++k) {
        const Vec3 p = randomPoint(rng, {-1, -1, -1}, {1, 1, 1}, 3);
        EXPECT_NEAR(value(sphere, 3, p), 0.5 - norm(p, {0.1, 0, 0}), 1e-14);
    }
    // Lipschitz across the symmetry planes, where the branches meet: pairs with coordinates that
    // are zero, tiny, or tiny of either sign.
    const double offsets[] = {0.0, 1e-300, 1e-12, -1e-12, 1e-7, -1e-7};
    std::normal_distribution<double> gauss(0.0, 1.0);
    const ShapeSpec nearRound = ellipsoid({0, 0, 0}, {0.5, 0.5 * (1 + 1e-13), 0.5 * (1 - 1e-14)});
    for (const auto& [dim, spec] :
         {std::pair{2, e}, std::pair{3, e}, std::pair{2, nearRound}, std::pair{3, nearRound}}) {
        const auto shape = makeShape(spec, dim, kVoxel);
        for (int k = 0; k < 20000; ++k) {
            Vec3 a = randomPoint(rng, {-1.5, -1, -0.6}, {1.5, 1, 0.6}, dim);
            if (k % 4 == 0)  // near the centre, where the nearest point is ill-determined
                for (int i = 0; i < dim; ++i) a[i] *= 1e-9;
            for (int i = 0; i < dim; ++i)
                if (rng() % 2) a[i] = offsets[rng() % 6];
            Vec3 b = a;
            const double scale = k % 2 ? 1e-6 : 0.05;
            for (int i = 0; i < dim; ++i) b[i] += rng() % 3 ? scale * gauss(rng) : 0.0;
            ASSERT_LE(std::abs(shape->value(a) - shape->value(b)), norm(a, b) * (1 + 1e-12) + 1e-15)
                << dim << "D: a = " << a[0] << ", " << a[1] << ", " << a[2] << "; b = " << b[0]
                << ", " << b[1] << ", " << b[2];
        }
    }
    const ShapeSpec circle = ellipsoid({0, 0, 0}, {0.5, 0.5, 0});
    EXPECT_NEAR(value(circle, 2, {0, 0, 0}), 0.5, 1e-15);
    EXPECT_NEAR(value(circle, 2, {0.3, 0.4, 0}), 0.0, 1e-15);
}

TEST(Shapes, RejectsInvalidShapes) {
    auto expectError = [](const ShapeSpec& spec, int dim, const std::string& needle) {
        try {
            makeShape(spec, dim, kVoxel);
            ADD_FAILURE() << "no error; expected one mentioning \"" << needle << "\"";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    expectError(cylinder({0, 0, 0}, 1, 1), 2, "3D");
    expectError(torus({0, 0, 0}, 1, 0.2), 2, "3D");
    ShapeSpec mesh;
    mesh.kind = ShapeKind::Mesh;
    mesh.meshFile = "whatever.obj";
    expectError(mesh, 2, "3D");
    expectError(ball({0, 0, 0}, -1), 2, "radius");
    expectError(ball({0, 0, 0}, 0), 3, "radius");
    expectError(ball({0, NAN, 0}, 1), 2, "center");
    expectError(box({0, 0, 0}, {1, 0, 0}), 2, "max");
    expectError(box({0, 0, 1}, {1, 1, 1}), 3, "max");
    expectError(ellipsoid({0, 0, 0}, {1, 0, 0}), 2, "radii");
    expectError(cylinder({0, 0, 0}, 1, 0), 3, "half_height");
    expectError(torus({0, 0, 0}, 1, -0.2), 3, "minor_radius");
    expectError(ball({0, 0, 0}, 1), 4, "dimension");
    // 2D boxes ignore the third axis entirely, even when min.z == max.z.
    EXPECT_NO_THROW(makeShape(box({0, 0, 0}, {1, 1, 0}), 2, kVoxel));
}

TEST(Domain, EmptyListIsTheWholeBox) {
    const Domain domain({}, 2, kVoxel);
    EXPECT_TRUE(domain.isWholeBox());
    EXPECT_EQ(domain.chi({0.3, 0.1, 0}), std::numeric_limits<double>::infinity());
}

TEST(Domain, AnnulusIsBallMinusBall) {
    const Domain annulus({ball({0, 0, 0}, 1.0), ball({0, 0, 0}, 0.5, CsgOp::Subtract)}, 2, kVoxel);
    EXPECT_FALSE(annulus.isWholeBox());
    EXPECT_DOUBLE_EQ(annulus.chi({0.75, 0, 0}), 0.25);
    EXPECT_DOUBLE_EQ(annulus.chi({0, -0.25, 0}), -0.25);
    EXPECT_DOUBLE_EQ(annulus.chi({0, 0, 0}), -0.5);
    EXPECT_DOUBLE_EQ(annulus.chi({1.5, 0, 0}), -0.5);
    EXPECT_EQ(annulus.chi({0.5, 0, 0}), 0.0);
    EXPECT_EQ(annulus.chi({0, 1, 0}), 0.0);
    EXPECT_DOUBLE_EQ(annulus.chi({0.6, 0.8, 3.0}), 0.0 + annulus.chi({0.6, 0.8, 0}));

    // Order matters: subtracting the big disk from the small one leaves nothing.
    const Domain nothing({ball({0, 0, 0}, 0.5), ball({0, 0, 0}, 1.0, CsgOp::Subtract)}, 2, kVoxel);
    std::mt19937 rng(1);
    for (int k = 0; k < 1000; ++k)
        EXPECT_LE(nothing.chi(randomPoint(rng, {-2, -2, 0}, {2, 2, 0}, 2)), 0.0);

    // A 3D shell, same rule.
    const Domain shell({ball({0, 0, 0}, 1.0), ball({0, 0, 0}, 0.5, CsgOp::Subtract)}, 3, kVoxel);
    EXPECT_DOUBLE_EQ(shell.chi({0, 0, 0.75}), 0.25);
    EXPECT_DOUBLE_EQ(shell.chi({0, 0, 0}), -0.5);
}

TEST(Domain, FirstShapeStartsTheDomainWhateverItsOp) {
    const Domain a({ball({0, 0, 0}, 1.0, CsgOp::Subtract)}, 2, kVoxel);
    const Domain b({ball({0, 0, 0}, 1.0, CsgOp::Intersect)}, 2, kVoxel);
    EXPECT_DOUBLE_EQ(a.chi({0.2, 0, 0}), 0.8);
    EXPECT_DOUBLE_EQ(b.chi({0.2, 0, 0}), 0.8);
}

TEST(Domain, UnionAndIntersection) {
    // Two disjoint disks.
    const Domain twoDisks({ball({-1, 0, 0}, 0.5), ball({1, 0, 0}, 0.5)}, 2, kVoxel);
    EXPECT_DOUBLE_EQ(twoDisks.chi({-1, 0, 0}), 0.5);
    EXPECT_DOUBLE_EQ(twoDisks.chi({1, 0, 0}), 0.5);
    EXPECT_DOUBLE_EQ(twoDisks.chi({0, 0, 0}), -0.5);

    // Ball ∩ box: the right half of the disk.
    const Domain half({ball({0, 0, 0}, 1.0), box({0, -2, 0}, {2, 2, 0}, CsgOp::Intersect)}, 2,
                      kVoxel);
    EXPECT_GT(half.chi({0.5, 0, 0}), 0.0);
    EXPECT_LT(half.chi({-0.5, 0, 0}), 0.0);
    EXPECT_DOUBLE_EQ(half.chi({0.5, 0, 0}), 0.5);
    EXPECT_DOUBLE_EQ(half.chi({0.1, 0, 0}), 0.1);

    // Three ops in sequence: (box ∪ disk) − small disk.
    const Domain seq(
        {box({-1, -1, 0}, {0, 1, 0}), ball({0, 0, 0}, 1.0), ball({0, 0, 0}, 0.25, CsgOp::Subtract)},
        2, kVoxel);
    EXPECT_LT(seq.chi({0, 0, 0}), 0.0);
    EXPECT_GT(seq.chi({-0.9, 0.9, 0}), 0.0);
    EXPECT_GT(seq.chi({0.6, 0, 0}), 0.0);
    EXPECT_LT(seq.chi({0.8, 0.8, 0}), 0.0);
}

TEST(Domain, CsgStaysLipschitz) {
    const Domain domain({box({-1, -1, -1}, {1, 1, 1}), torus({0, 0, 0}, 0.6, 0.2),
                         ball({0.5, 0.5, 0.5}, 0.6, CsgOp::Subtract),
                         cylinder({0, 0, 0}, 0.9, 2.0, CsgOp::Intersect)},
                        3, kVoxel);
    std::mt19937 rng(11);
    std::normal_distribution<double> gauss(0.0, 1.0);
    for (double scale : {1e-3, 0.1, 1.0})
        for (int k = 0; k < 5000; ++k) {
            const Vec3 a = randomPoint(rng, {-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}, 3);
            const Vec3 b{a[0] + scale * gauss(rng), a[1] + scale * gauss(rng),
                         a[2] + scale * gauss(rng)};
            ASSERT_LE(std::abs(domain.chi(a) - domain.chi(b)), norm(a, b) * (1 + 1e-12));
        }
}

TEST(Domain, ErrorsNameTheShape) {
    try {
        Domain({ball({0, 0, 0}, 1.0), torus({0, 0, 0}, 0.5, 0.1)}, 2, kVoxel);
        FAIL() << "a torus in 2D must be rejected";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("[[domain]] #2 (torus)"), std::string::npos) << what;
        EXPECT_NE(what.find("3D"), std::string::npos) << what;
    }
    try {
        Domain({ball({0, 0, 0}, -1.0)}, 3, kVoxel);
        FAIL() << "a negative radius must be rejected";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("[[domain]] #1 (ball): radius"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace modeflow
