/// @file VortexProjectionTest.cpp
/// Analytic vortices → modal states: the projection is the ⋆-inner product with each mode (a round
/// trip for fields in the basis), a centred Lamb–Oseen vortex in a disk lands on the axisymmetric
/// modes with the right sense of rotation, and a 3D ring projects linearly in its circulation.
/// The MHD rotor's uniform magnetic field (UniformField.h) is uniform inside, tangent at the wall,
/// projected as the least-squares fit, and the wall layer is what makes it representable.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/QR>

#include "engine/core/Error.h"
#include "precompute/Precompute.h"
#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellDec.h"
#include "precompute/initial/UniformField.h"
#include "precompute/initial/VortexProjection.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

constexpr int kDiskCells = 32;

/// A unit disk on a grid symmetric about the origin (so a 90° turn maps faces onto faces).
const BasisCache& disk() {
    static const BasisCache cache = [] {
        SceneSpec scene = testing::unitBallScene(2, kDiskCells, 10, 0);
        Progress quiet = Progress::silent();
        return computeBasis(scene, quiet);
    }();
    return cache;
}

/// A grid with no periodic axis, for velocities at points.
GridSpec plainGrid(int dim) {
    GridSpec grid;
    grid.dim = dim;
    return grid;
}

VortexSpec vortex2d(Vec3 centre, double strength, double sigma) {
    VortexSpec v;
    v.center = centre;
    v.strength = strength;
    v.radius = sigma;
    return v;
}

/// Face velocities u·n = ⋆F / |dual face| of a flux field, keyed by (normal, i, j).
std::map<std::tuple<int, int, int>, double> faceVelocities(const BasisCache& cache,
                                                           const Eigen::VectorXd& flux) {
    const CubicalComplex cx(cache.grid);
    std::map<std::tuple<int, int, int>, double> u;
    for (std::size_t f = 0; f < cache.faces.size(); ++f) {
        const Element e = cx.element(1, cache.faces[f]);
        const int normal = (e.axes & 1u) ? 1 : 0;
        const auto i = static_cast<Eigen::Index>(f);
        u[{normal, e.pos[0], e.pos[1]}] = flux[i] * cache.faceStar[i] / dualMeasure(cache.grid, e);
    }
    return u;
}

/// How far a mode is from its own 90° turn about the origin, relative to its size.
double turnDefect(const BasisCache& cache, int mode) {
    const auto u = faceVelocities(cache, cache.velocity.modes.col(mode));
    double diff = 0.0, size = 0.0;
    for (const auto& [key, value] : u) {
        const auto [normal, i, j] = key;
        // (x, y) → (−y, x): an x-flux at (i, j) becomes a +y flux at (N−1−j, i); a y-flux at
        // (i, j) becomes a −x flux at (N−j, i).
        const auto turned =
            normal == 0 ? std::tuple{1, kDiskCells - 1 - j, i} : std::tuple{0, kDiskCells - j, i};
        const double sign = normal == 0 ? 1.0 : -1.0;
        const auto it = u.find(turned);
        const double image = it == u.end() ? 0.0 : sign * it->second;
        diff += (image - value) * (image - value);
        size += value * value;
    }
    return std::sqrt(diff / size);
}

TEST(VortexProjection, ABasisModeRoundTripsToItsUnitVector) {
    const BasisCache& cache = disk();
    const Eigen::VectorXd v = projectFluxes(cache, cache.velocity.modes.col(2));
    Eigen::VectorXd e3 = Eigen::VectorXd::Zero(v.size());
    e3[2] = 1.0;
    EXPECT_LE((v - e3).cwiseAbs().maxCoeff(), 1e-12) << v.transpose();
    EXPECT_THROW(projectFluxes(cache, Eigen::VectorXd::Zero(3)), Error);
}

TEST(VortexProjection, LambOseenVelocityHasTheAnalyticProfile) {
    const VortexSpec v = vortex2d({0.2, -0.1, 0.0}, 2.0, 0.3);
    const VortexSpec list[] = {v};
    // At r = σ to the right of the centre: speed Γ/(2πσ)(1 − 1/e), pointing +y for Γ > 0.
    const Vec3 u = vortexVelocity(list, plainGrid(2), {0.5, -0.1, 0.0});
    EXPECT_NEAR(u[0], 0.0, 1e-15);
    EXPECT_NEAR(u[1], 2.0 / (2.0 * std::numbers::pi * 0.3) * (1.0 - std::exp(-1.0)), 1e-14);
    // The core rotates rigidly at Γ/(2πσ²); the centre itself is still.
    const Vec3 centre = vortexVelocity(list, plainGrid(2), v.center);
    EXPECT_EQ(centre[0], 0.0);
    EXPECT_EQ(centre[1], 0.0);
    const Vec3 nearCentre = vortexVelocity(list, plainGrid(2), {0.2, -0.1 + 1e-9, 0.0});
    const double rigid = -2.0 / (2.0 * std::numbers::pi * 0.09) * 1e-9;
    EXPECT_NEAR(nearCentre[0], rigid, 1e-6 * std::abs(rigid));
}

TEST(VortexProjection, CentredVortexLandsOnAxisymmetricModesTurningTheRightWay) {
    const BasisCache& cache = disk();
    const VortexSpec list[] = {vortex2d({0.0, 0.0, 0.0}, 1.0, 0.25)};
    const Eigen::VectorXd v = projectVortices(cache, list, 0.0);
    ASSERT_GT(v.squaredNorm(), 0.0);

    double axisymmetric = 0.0;
    int count = 0;
    for (int k = 0; k < v.size(); ++k) {
        if (turnDefect(cache, k) < 1e-6) {
            axisymmetric += v[k] * v[k];
            ++count;
        }
    }
    EXPECT_GE(count, 1);
    EXPECT_GE(axisymmetric / v.squaredNorm(), 0.9)
        << count << " turn-invariant modes; state " << v.transpose();

    // Reconstructed: to the right of the centre the flow goes up, to the left down.
    const Eigen::VectorXd flux = cache.velocity.modes * v;
    const auto u = faceVelocities(cache, flux);
    // y-normal faces on the row y = 0 (j = N/2), x ≈ ±0.34.
    EXPECT_GT(u.at({1, 20, kDiskCells / 2}), 0.0);
    EXPECT_LT(u.at({1, kDiskCells - 1 - 20, kDiskCells / 2}), 0.0);

    // Asking for an energy rescales; a negative circulation flips the state.
    const Eigen::VectorXd scaled = projectVortices(cache, list, 3.0);
    EXPECT_NEAR(0.5 * scaled.squaredNorm(), 3.0, 1e-12);
    EXPECT_NEAR((scaled.normalized() - v.normalized()).norm(), 0.0, 1e-12);
    const VortexSpec reversed[] = {vortex2d({0.0, 0.0, 0.0}, -1.0, 0.25)};
    EXPECT_LE((projectVortices(cache, reversed, 0.0) + v).norm(), 1e-12 * v.norm());
}

TEST(VortexProjection, VorticesOutsideTheDomainCannotBeRescaled) {
    const BasisCache& cache = disk();
    const VortexSpec none[] = {vortex2d({0.0, 0.0, 0.0}, 0.0, 0.25)};
    EXPECT_THROW(projectVortices(cache, none, 1.0), Error);
    EXPECT_THROW(projectVortices(cache, {}, 0.0), Error);
}

VortexSpec ring(double strength) {
    VortexSpec v;
    v.center = {0.0, 0.0, 0.1};
    v.normal = {0.0, 0.0, 1.0};
    v.ringRadius = 0.4;
    v.radius = 0.15;
    v.strength = strength;
    return v;
}

TEST(VortexProjection, RingVelocityAtItsCentreFollowsTheNormal) {
    // Rosenhead–Moore at the centre: u = Γ R² / (2 (R² + σ²)^{3/2}) along +normal.
    const VortexSpec list[] = {ring(1.5)};
    const Vec3 u = vortexVelocity(list, plainGrid(3), list[0].center);
    const double R = 0.4, s = 0.15;
    const double expected = 1.5 * R * R / (2.0 * std::pow(R * R + s * s, 1.5));
    EXPECT_NEAR(u[0], 0.0, 1e-12);
    EXPECT_NEAR(u[1], 0.0, 1e-12);
    // Chords sit at R cos(π/128) from the centre: a relative error ~ (π/128)².
    EXPECT_NEAR(u[2], expected, 1e-3 * expected);
}

TEST(VortexProjection, RingProjectsWithEnergyQuadraticInCirculation) {
    SceneSpec scene = testing::unitBallScene(3, 14, 24, 0);
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);

    const VortexSpec one[] = {ring(1.0)};
    const VortexSpec two[] = {ring(2.5)};
    const Eigen::VectorXd v1 = projectVortices(cache, one, 0.0);
    const Eigen::VectorXd v2 = projectVortices(cache, two, 0.0);
    const double e1 = 0.5 * v1.squaredNorm(), e2 = 0.5 * v2.squaredNorm();
    // 24 modes reach the ball's first axisymmetric poloidal modes, which carry the ring's flow
    // (the first 8 are orthogonal to it).
    EXPECT_GT(e1, 1e-2);
    EXPECT_NEAR(e2 / e1, 2.5 * 2.5, 1e-10);
}

/// A periodic grid over [0, 2] × [0, 2] (2D) or [0, 2]³, periodic as `periodic` says.
GridSpec periodicGrid(int dim, std::array<bool, 3> periodic, int cells = 32) {
    const double z = dim == 3 ? 2.0 : 0.0;
    GridSpec grid =
        testing::gridScene({cells, cells, cells}, {0.0, 0.0, 0.0}, {2.0, 2.0, z}, dim).grid;
    grid.periodic = periodic;
    return grid;
}

double maxDifference(const Vec3& a, const Vec3& b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

/// Points spread over [0, 2]^dim.
std::vector<Vec3> samplePoints(int dim) {
    std::vector<Vec3> points;
    for (int i = 0; i < 40; ++i)
        points.push_back({std::fmod(0.137 + 0.618 * i, 2.0), std::fmod(1.91 + 0.414 * i, 2.0),
                          dim == 3 ? std::fmod(0.7 + 0.273 * i, 2.0) : 0.0});
    return points;
}

TEST(PeriodicVortices, WrapEveryPeriodicAxisAndMoveWithTheirCentres) {
    // Periodic in x: the same field one period on; shifting every vortex shifts the field, across
    // the seam too. A Lamb–Oseen pair in 2D (channel, column, torus) and a ring in 3D.
    for (const auto& [dim, periodic] :
         {std::pair{2, std::array{true, false, false}},
          std::pair{2, std::array{false, true, false}}, std::pair{2, std::array{true, true, false}},
          std::pair{3, std::array{true, true, true}}}) {
        const GridSpec grid = periodicGrid(dim, periodic, 8);
        std::vector<VortexSpec> middle;
        if (dim == 2) {
            middle = {vortex2d({0.8, 1.1, 0.0}, 1.0, 0.15), vortex2d({1.2, 0.9, 0.0}, -1.0, 0.15)};
        } else {
            VortexSpec r = ring(1.0);
            r.center = {1.0, 1.0, 1.0};
            r.normal = {0.0, 0.3, 1.0};
            middle = {r};
        }
        const Vec3 shift{periodic[0] ? 0.97 : 0.0, periodic[1] ? 1.03 : 0.0,
                         periodic[2] ? 0.91 : 0.0};
        std::vector<VortexSpec> seam = middle;
        for (VortexSpec& v : seam)
            for (int k = 0; k < 3; ++k) v.center[k] = std::fmod(v.center[k] + shift[k], 2.0);
        for (const Vec3& x : samplePoints(dim)) {
            const Vec3 u = vortexVelocity(middle, grid, x);
            Vec3 moved = x, wrapped = x;
            for (int k = 0; k < 3; ++k) moved[k] += shift[k];
            for (int k = 0; k < dim; ++k) wrapped[k] += periodic[k] ? 2.0 : 0.0;
            EXPECT_LE(maxDifference(vortexVelocity(seam, grid, moved), u), 1e-12)
                << dim << "D, x = " << x[0] << ", " << x[1];
            EXPECT_LE(maxDifference(vortexVelocity(middle, grid, wrapped), u), 1e-12)
                << dim << "D, x = " << x[0] << ", " << x[1];
        }
    }
}

TEST(PeriodicVortices, AChannelsVortexIsTheSumOfItsImages) {
    // Along one periodic axis, the closed form is the sum of the vortex's images, m = −M..M
    // (converging as 1/M); for x and for y.
    const VortexSpec v = vortex2d({0.3, 1.7, 0.0}, 1.3, 0.4);
    for (const int axis : {0, 1}) {
        std::array<bool, 3> periodic{false, false, false};
        periodic[axis] = true;
        const GridSpec grid = periodicGrid(2, periodic);
        for (const Vec3& x : samplePoints(2)) {
            Vec3 sum{0.0, 0.0, 0.0};
            constexpr int kImages = 20000;
            for (int m = -kImages; m <= kImages; ++m) {
                VortexSpec image = v;
                image.center[axis] += 2.0 * m;
                const VortexSpec one[] = {image};
                const Vec3 u = vortexVelocity(one, plainGrid(2), x);
                for (int k = 0; k < 2; ++k) sum[k] += u[k];
            }
            const VortexSpec one[] = {v};
            EXPECT_LE(maxDifference(vortexVelocity(one, grid, x), sum), 1e-4)
                << "axis " << axis << ", x = " << x[0] << ", " << x[1];
        }
    }
}

TEST(PeriodicVortices, ATorusPairIsThePeriodicFlowOfItsVorticity) {
    // Doubly periodic: the velocity of the pair's Gaussian vorticity (with its images) solved
    // spectrally, u = ∇⊥ψ, −Δψ = ω, the mean flow zero.
    const std::vector<VortexSpec> pair{vortex2d({0.1, 1.8, 0.0}, 1.0, 0.2),
                                       vortex2d({1.5, 0.4, 0.0}, -1.0, 0.2)};
    const GridSpec grid = periodicGrid(2, {true, true, false});
    const double length = 2.0, k0 = 2.0 * std::numbers::pi / length;
    for (const Vec3& x : samplePoints(2)) {
        Vec3 spectral{0.0, 0.0, 0.0};
        constexpr int kWaves = 40;  // e^{−k²σ²/4} < 1e-16 beyond
        for (int a = -kWaves; a <= kWaves; ++a)
            for (int b = -kWaves; b <= kWaves; ++b) {
                if (a == 0 && b == 0) continue;
                const double kx = k0 * a, ky = k0 * b, k2 = kx * kx + ky * ky;
                for (const VortexSpec& v : pair) {
                    // ω̂ = Γ/|box| e^{−k²σ²/4} e^{−ik·c}; u = Re Σ i k_y ψ̂ e^{ik·x}, v = −Re Σ i k_x
                    // ψ̂ e^{ik·x}.
                    const double amplitude = v.strength / (length * length) *
                                             std::exp(-k2 * v.radius * v.radius / 4) / k2;
                    const double phase = kx * (x[0] - v.center[0]) + ky * (x[1] - v.center[1]);
                    spectral[0] -= amplitude * ky * std::sin(phase);
                    spectral[1] += amplitude * kx * std::sin(phase);
                }
            }
        EXPECT_LE(maxDifference(vortexVelocity(pair, grid, x), spectral), 1e-9)
            << "x = " << x[0] << ", " << x[1];
    }
}

TEST(PeriodicVortices, APairOnTheSeamOfATorusHasTheEnergyOfOneInTheMiddle) {
    // What was reported: 0.147 in the middle, 0.045 centred on the seam.
    SceneSpec scene = testing::gridScene({32, 32, 1}, {0.0, 0.0, 0.0}, {2.0, 2.0, 0.0}, 2);
    scene.grid.periodic = {true, true, false};
    scene.basis.velocityModes = {{1, 40}};
    scene.basis.scalarModes = 0;
    Progress quiet = Progress::silent();
    const BasisCache cache = computeBasis(scene, quiet);
    const auto energy = [&](double cx, double cy) {
        const VortexSpec pair[] = {vortex2d({cx - 0.3, cy, 0.0}, 1.0, 0.2),
                                   vortex2d({cx + 0.3, cy, 0.0}, -1.0, 0.2)};
        return 0.5 * projectVortices(cache, pair, 0.0).squaredNorm();
    };
    const double middle = energy(1.0, 1.0);
    EXPECT_GT(middle, 1e-3);
    for (const auto& [cx, cy] :
         {std::pair{0.0, 1.0}, std::pair{1.0, 0.0}, std::pair{0.0, 0.0}, std::pair{2.0, 2.0}})
        EXPECT_NEAR(energy(cx, cy) / middle, 1.0, 1e-9) << "centred at " << cx << ", " << cy;
}

/// A unit disk at 48² with 40 modes: enough for the interior of a uniform field to be resolved.
const BasisCache& disk40() {
    static const BasisCache cache = [] {
        SceneSpec scene = testing::unitBallScene(2, 48, 40, 0);
        Progress quiet = Progress::silent();
        return computeBasis(scene, quiet);
    }();
    return cache;
}

const std::vector<ShapeSpec> kUnitDisk{testing::ball({0.0, 0.0, 0.0}, 1.0)};

TEST(UniformField, IsUniformInsideDivergenceFreeAndTangentAtTheWall) {
    const UniformField field(disk(), kUnitDisk, {2.0, 1.0, 0.0}, 1.5, 0.3);
    const double bx = 1.5 * 2.0 / std::sqrt(5.0), by = 1.5 / std::sqrt(5.0);
    for (const Vec3& x : {Vec3{0.0, 0.0, 0.0}, Vec3{0.45, -0.5, 0.0}, Vec3{-0.69, 0.0, 0.0}}) {
        const Vec3 b = field(x);
        EXPECT_NEAR(b[0], bx, 1e-12);
        EXPECT_NEAR(b[1], by, 1e-12);
    }
    const double h = 1e-5;
    for (double angle = 0.1; angle < 6.28; angle += 0.37) {
        const Vec3 n{std::cos(angle), std::sin(angle), 0.0};
        // In the layer: divergence-free (central differences, to their truncation error).
        const double r = 0.85;
        const auto at = [&](double dx, double dy) {
            return field({r * n[0] + dx, r * n[1] + dy, 0.0});
        };
        const double divergence =
            (at(h, 0)[0] - at(-h, 0)[0] + at(0, h)[1] - at(0, -h)[1]) / (2 * h);
        EXPECT_NEAR(divergence, 0.0, 1e-4) << angle;
        // At the wall: no normal component; outside: no field.
        const Vec3 wall = field({0.999 * n[0], 0.999 * n[1], 0.0});
        EXPECT_NEAR(wall[0] * n[0] + wall[1] * n[1], 0.0, 1e-3) << angle;
        const Vec3 outside = field({1.05 * n[0], 1.05 * n[1], 0.0});
        EXPECT_EQ(outside[0], 0.0);
        EXPECT_EQ(outside[1], 0.0);
    }
    EXPECT_THROW(UniformField(disk(), kUnitDisk, {0.0, 0.0, 0.0}, 1.0, 0.3), Error);
    EXPECT_THROW(UniformField(disk(), kUnitDisk, {1.0, 0.0, 0.0}, 1.0, 0.0), Error);
}

TEST(UniformField, IsUniformUpToTheEndsOfPeriodicAxes) {
    // A channel periodic along x between walls at y = ±1: no layer at x = ±1, one at y = ±1.
    BasisCache channel;
    channel.grid = testing::gridScene({16, 16, 1}, {-1.0, -1.0, 0.0}, {1.0, 1.0, 0.0}, 2).grid;
    channel.grid.periodic = {true, false, false};
    const UniformField field(channel, {}, {1.0, 0.0, 0.0}, 2.0, 0.3);
    for (const double x : {-0.999, -0.9, 0.0, 0.95, 0.999}) {
        const Vec3 b = field({x, 0.0, 0.0});
        EXPECT_NEAR(b[0], 2.0, 1e-12) << "x = " << x;
        EXPECT_NEAR(b[1], 0.0, 1e-12) << "x = " << x;
    }
    EXPECT_NEAR(field({0.0, 0.999, 0.0})[1], 0.0, 1e-3) << "tangent at a wall";
    EXPECT_LT(field({0.0, 0.999, 0.0})[0], 0.1) << "faded out at a wall";
}

TEST(UniformField, WrapsPeriodicSeamsWhereWallsMeetThem) {
    // A 3D channel periodic along x between walls in y and z: a field across y turns back along
    // the z walls. Across the seam x = ±1 it goes on continuously, next to the walls too (the
    // symmetric gauge's potential grows along x there, and jumped); divergence-free throughout.
    BasisCache channel;
    channel.grid = testing::gridScene({8, 8, 8}, {-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}, 3).grid;
    channel.grid.periodic = {true, false, false};
    const UniformField field(channel, {}, {0.3, 1.0, 0.4}, 1.0, 0.3);
    const double h = 1e-5;
    for (const double y : {-0.9, -0.2, 0.85})
        for (const double z : {-0.92, 0.1, 0.9}) {
            EXPECT_LE(maxDifference(field({1.0 - 1e-9, y, z}), field({-1.0 + 1e-9, y, z})), 1e-6)
                << "y = " << y << ", z = " << z;
            const auto at = [&](double dx, double dy, double dz) {
                return field({-0.99 + dx, y + dy, z + dz});
            };
            const double divergence = (at(h, 0, 0)[0] - at(-h, 0, 0)[0] + at(0, h, 0)[1] -
                                       at(0, -h, 0)[1] + at(0, 0, h)[2] - at(0, 0, -h)[2]) /
                                      (2 * h);
            EXPECT_NEAR(divergence, 0.0, 1e-4) << "y = " << y << ", z = " << z;
        }
    EXPECT_NEAR(field({0.0, 0.0, 0.0})[1], 1.0 / std::sqrt(1.25), 1e-12) << "uniform inside";
    // Where the section across an axis closes on itself through periodic axes, no field crosses
    // it on average: refused, naming the axis (2D channel along x: y; 3D slab periodic in x, y: z).
    BasisCache channel2d;
    channel2d.grid = testing::gridScene({16, 16, 1}, {-1.0, -1.0, 0.0}, {1.0, 1.0, 0.0}, 2).grid;
    channel2d.grid.periodic = {true, false, false};
    BasisCache slab = channel;
    slab.grid.periodic = {true, true, false};
    for (const auto& [cache, direction, axis] : {std::tuple{&channel2d, Vec3{0.2, 1.0, 0.0}, "y"},
                                                 std::tuple{&slab, Vec3{0.0, 0.0, 1.0}, "z"}}) {
        try {
            UniformField(*cache, {}, direction, 1.0, 0.3);
            ADD_FAILURE() << "a field across " << axis << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("a component along ") + axis +
                                                 " crosses the walls"),
                      std::string::npos)
                << e.what();
        }
    }
    const UniformField along(slab, {}, {1.0, 0.5, 0.0}, 1.0, 0.3);
    EXPECT_LE(maxDifference(along({1.0 - 1e-9, 0.3, 0.95}), along({-1.0 + 1e-9, 0.3, 0.95})), 1e-6);
    EXPECT_LE(maxDifference(along({0.3, 1.0 - 1e-9, 0.95}), along({0.3, -1.0 + 1e-9, 0.95})), 1e-6);
}

TEST(UniformField, ProjectionIsTheLeastSquaresFitAndDivergenceFree) {
    const BasisCache& cache = disk();
    const UniformField field(cache, kUnitDisk, {1.0, 0.0, 0.0}, 1.0, uniformFieldLayer(cache));
    const Eigen::VectorXd f = projectUniformField(cache, field);
    ASSERT_GT(f.norm(), 0.0);
    // The ⋆-weighted least-squares fit of the face fluxes by the modes, solved directly.
    const Eigen::VectorXd flux = faceFluxes(cache, [&](const Vec3& x) { return field(x); });
    const Eigen::VectorXd root = cache.faceStar.cwiseSqrt();
    const Eigen::MatrixXd a = root.asDiagonal() * cache.velocity.modes;
    const Eigen::VectorXd fit = a.colPivHouseholderQr().solve(root.cwiseProduct(flux));
    EXPECT_LE((f - fit).norm(), 1e-10 * f.norm());
    // Σ F_i Ψ_i is divergence-free on the full grid (no flux leaks through a non-DOF face).
    const CubicalComplex complex(cache.grid);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(complex.count(1));
    const Eigen::VectorXd faces = cache.velocity.modes * f;
    for (std::size_t i = 0; i < cache.faces.size(); ++i)
        full[cache.faces[i]] = faces[Eigen::Index(i)];
    const Eigen::VectorXd divergence = complex.incidence(1) * full;
    EXPECT_LE(divergence.cwiseAbs().maxCoeff(), 1e-12 * full.cwiseAbs().maxCoeff());
}

TEST(UniformField, OnlyTheWallLayerMakesAUniformFieldRepresentable) {
    const BasisCache& cache = disk40();
    // A plain uniform field is a gradient: ⋆-orthogonal to every tangential div-free mode.
    const Eigen::VectorXd plain = projectFluxes(cache, faceFluxes(cache, [](const Vec3&) {
                                                    return Vec3{1.0, 0.0, 0.0};
                                                }));
    const UniformField field(cache, kUnitDisk, {1.0, 0.0, 0.0}, 1.0, uniformFieldLayer(cache));
    const Eigen::VectorXd f = projectUniformField(cache, field);
    // Reconstructed, it points left to right inside, at about the given strength.
    const auto u = faceVelocities(cache, cache.velocity.modes * f);
    const double h = 2.2 / 48;
    double sum = 0.0, sumSquares = 0.0, cross = 0.0;
    int count = 0;
    for (const auto& [key, value] : u) {
        const auto [normal, i, j] = key;
        const double x = -1.1 + (i + (normal == 0 ? 0.0 : 0.5)) * h,
                     y = -1.1 + (j + (normal == 1 ? 0.0 : 0.5)) * h;
        if (x * x + y * y > 0.4 * 0.4) continue;
        if (normal == 0) {
            sum += value;
            sumSquares += value * value;
            ++count;
        } else {
            cross = std::max(cross, std::abs(value));
        }
    }
    const double mean = sum / count, spread = std::sqrt(sumSquares / count - mean * mean);
    std::cout << "uniform field, 40 modes, layer " << uniformFieldLayer(cache)
              << ": |plain projection| " << plain.norm() << ", |F| " << f.norm() << ", interior Bx "
              << mean << " ± " << spread << ", max |By| " << cross << "\n";
    // Measured: 1.7e-14 against 1.87; interior Bx 0.97 ± 0.15, |By| ≤ 0.19 (40 modes resolve
    // the turn at the wall only roughly; 100 do better).
    EXPECT_LE(plain.norm(), 1e-10 * f.norm());
    EXPECT_NEAR(mean, 1.0, 0.05);
    EXPECT_LE(spread, 0.2);
    EXPECT_LE(cross, 0.25);
}

}  // namespace
}  // namespace modeflow
