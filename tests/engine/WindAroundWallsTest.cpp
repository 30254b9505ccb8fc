/// @file WindAroundWallsTest.cpp
/// A wind round [[domain]] walls (engine/README.md, "Wind"): the held flow the precompute stores
/// is a discrete potential flow (divergence-free in every cut cell, curl-free, none through the
/// walls, about twice the wind over a cylinder's crown), its vorticity-form term equals the
/// advective form where both apply, and the midpoint rule's energy changes by h v̄ᵀDv̄ to round-off.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/FaceLocation.h"
#include "engine/core/MacGrid.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/simulation/WindTransport.h"
#include "tests/support/EnergyBudget.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// [0, 2] × [0, 1] in 64 × 32 cells round a hole of radius 0.17 at (1, 0.5): the domain box
/// reaches past the grid, so the walls are the grid's sides and the hole's.
SceneSpec holeInAChannel(std::array<bool, 3> periodic = {false, false, false}) {
    SceneSpec scene = testing::gridScene({64, 32, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2);
    scene.grid.periodic = periodic;
    scene.domain = {testing::box({-1.0, -1.0, 0.0}, {3.0, 2.0, 0.0}),
                    testing::ball({1.0, 0.5, 0.0}, 0.17, CsgOp::Subtract)};
    scene.basis.velocityModes = {{1, 40}};
    scene.basis.scalarModes = 0;
    return scene;
}

/// Checks a unit wind's flow along +a face by face: none through a solid face or a wall the
/// wind does not cross, the upstream side exactly the wind, the downstream side within
/// `outflowTolerance` of it (the sides are whole: the hole is far from them). Returns |face ∩ Ω|
/// per grid face where the flow may cross it, −1 elsewhere.
std::vector<double> checkedAreas(const BasisCache& cache, int a, const std::vector<double>& flow,
                                 double outflowTolerance) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    std::vector<double> area(std::size_t(grid.faceTotal()), -1.0);
    for (std::size_t d = 0; d < cache.faces.size(); ++d) {
        const int c = locateFace(grid, cache.faces[d]).axis;
        area[std::size_t(cache.faces[d])] = grid.spacing[c] / cache.faceStar[Eigen::Index(d)];
    }
    for (int axis = 0; axis < grid.dim; ++axis)
        forEachFace(grid, axis, [&](std::int64_t face, std::array<int, 3> p) {
            const auto f = std::size_t(face);
            if (area[f] >= 0.0) return;
            if (axis == a && (p[a] == 0 || p[a] == grid.cells[a])) {
                area[f] = grid.faceArea(a);
                if (p[a] == 0)
                    EXPECT_EQ(flow[f], 1.0) << "inflow face " << f;
                else
                    EXPECT_NEAR(flow[f], 1.0, outflowTolerance) << "outflow face " << f;
            } else {
                EXPECT_EQ(flow[f], 0.0) << "face " << f << " has no fluid";
            }
        });
    return area;
}

/// The largest net outflow of a fluid cell, over a cell's side (|div| h).
double worstDivergence(const BasisCache& cache, const std::vector<double>& flow,
                       const std::vector<double>& area) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    double worst = 0.0;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                if (cache.cellFraction[std::size_t(grid.cellIndex(x, y, z))] <= 0.0) continue;
                double out = 0.0;
                for (int axis = 0; axis < grid.dim; ++axis) {
                    const auto low = std::size_t(grid.faceIndex(axis, x, y, z)),
                               high = std::size_t(grid.upperFaceIndex(axis, x, y, z));
                    out += flow[high] * std::max(area[high], 0.0) -
                           flow[low] * std::max(area[low], 0.0);
                }
                worst = std::max(worst, std::abs(out) / grid.faceArea(0));
            }
    return worst;
}

TEST(WindAroundWalls, TheHeldFlowIsAPotentialFlowRoundTheHole) {
    const RunInputs run = testing::sharedRun(holeInAChannel());
    const BasisCache& cache = run.cache;
    ASSERT_EQ(cache.windBase.size(), 4u);
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const double h = grid.spacing[0];
    const auto face = [&](int axis, int x, int y) {
        return std::size_t(grid.faceIndex(axis, x, y, 0));
    };
    for (int a = 0; a < 2; ++a) {
        const std::vector<double>& b = cache.windBase[std::size_t(2 * a)];  // along +a
        // The downstream side: close to the hole along y.
        const std::vector<double> area = checkedAreas(cache, a, b, a == 0 ? 0.1 : 0.5);
        double worstCurl = 0.0, crown = 0.0;
        for (int y = 1; y < grid.cells[1]; ++y)
            for (int x = 1; x < grid.cells[0]; ++x) {
                const std::size_t left = face(1, x - 1, y), right = face(1, x, y),
                                  below = face(0, x, y - 1), above = face(0, x, y);
                if (std::min({area[left], area[right], area[below], area[above]}) < 0.0) continue;
                const double curl = (b[right] - b[left]) / h - (b[above] - b[below]) / h;
                worstCurl = std::max(worstCurl, std::abs(curl) * h);
            }
        // Over the hole's crown (x = 1) the air runs about twice the wind (2 in an unbounded
        // flow; the channel's walls add to it).
        if (a == 0)
            for (int y = 0; y < grid.cells[1]; ++y) crown = std::max(crown, b[face(0, 32, y)]);
        const double divergence = worstDivergence(cache, b, area);
        EXPECT_LE(divergence, 1e-10) << "axis " << a;
        EXPECT_LE(worstCurl, 1e-10) << "axis " << a;
        if (a == 0) {
            EXPECT_GT(crown, 1.8);
            EXPECT_LT(crown, 2.6);
        }
        std::printf(
            "[ measured ] unit wind along %c round a hole of radius 0.17 in 64 x 32: worst "
            "|div| %.1e, worst |curl| h %.1e%s\n",
            "xy"[a], divergence, worstCurl,
            a == 0 ? (", crown speed " + std::to_string(crown)).c_str() : "");
    }
    // A whole box's flow is the constant wind: the cache holds none.
    SceneSpec whole = holeInAChannel();
    whole.domain.clear();
    whole.basis.velocityModes = {{1, 10}};
    EXPECT_TRUE(testing::sharedRun(whole).cache.windBase.empty());
}

TEST(WindAroundWalls, RoundABallInABoxTheAirRunsHalfAsFastAgainAtItsEquator) {
    // A ball of radius 0.2 in a 3D box of 24 × 16 × 16 cells: the potential flow past a sphere
    // runs at 1.5 U on its equator, falling off as 1 + R³/2r³ (the box's walls add to it).
    SceneSpec scene = testing::gridScene({24, 16, 16}, {0.0, 0.0, 0.0}, {1.5, 1.0, 1.0}, 3);
    scene.domain = {testing::box({-1.0, -1.0, -1.0}, {3.0, 2.0, 2.0}),
                    testing::ball({0.75, 0.5, 0.5}, 0.2, CsgOp::Subtract)};
    scene.basis.velocityModes = {{1, 20}};
    scene.basis.scalarModes = 0;
    const RunInputs run = testing::sharedRun(scene);
    ASSERT_EQ(run.cache.windBase.size(), 6u);
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
    for (int a = 0; a < 3; ++a) {
        const std::vector<double>& b = run.cache.windBase[std::size_t(2 * a)];
        const double divergence =
            worstDivergence(run.cache, b, checkedAreas(run.cache, a, b, 0.15));
        EXPECT_LE(divergence, 1e-10) << "axis " << a;
        // The fastest face normal to a in the plane through the centre across a.
        double equator = 0.0;
        forEachFace(grid, a, [&](std::int64_t face, std::array<int, 3> p) {
            if (p[a] == grid.cells[a] / 2) equator = std::max(equator, b[std::size_t(face)]);
        });
        EXPECT_GT(equator, 1.2) << "axis " << a;
        EXPECT_LT(equator, 1.8) << "axis " << a;
        std::printf(
            "[ measured ] unit wind along %c round a ball of radius 0.2 in 24 x 16 x 16: "
            "worst |div| %.1e, equator speed %.3f\n",
            "xyz"[a], divergence, equator);
    }
}

TEST(WindAroundWalls, ItsVorticityFormEqualsTheAdvectiveFormOnAPeriodicChannel) {
    // A periodic channel whose domain holds the whole grid: the cache's flow along x is the
    // constant 1, so D is the advective form alone. Doubled, the vorticity form of the same U
    // adds to it: on a uniform periodic lattice the two are one discrete operator of
    // −⟨Ψ_k, (U·∇)Ψ_j⟩, to round-off (so the potential part's sign and scale are the term's).
    SceneSpec scene = holeInAChannel({true, false, false});
    scene.domain.pop_back();
    RunInputs run = testing::sharedRun(scene);
    ASSERT_EQ(run.cache.windBase.size(), 4u);
    for (const double b : run.cache.windBase[0])
        ASSERT_NEAR(std::abs(b) > 0.0 ? b : 1.0, 1.0, 1e-9);
    const WindSpec wind{{0.7, 0.0, 0.0}};
    const Eigen::MatrixXd advective = WindTransport(run.cache, wind).matrix();
    for (double& b : run.cache.windBase[0]) b *= 2.0;
    const Eigen::MatrixXd vorticity = WindTransport(run.cache, wind).matrix() - advective;
    const double scale = advective.norm();
    const double gap = (vorticity - advective).norm() / scale;
    EXPECT_GT(scale, 1.0) << "the wind turns the modes";
    EXPECT_LE(gap, 1e-12);
    std::printf(
        "[ measured ] vorticity form vs advective form of one wind on a periodic channel, "
        "40 modes: relative difference %.2e\n",
        gap);
}

TEST(WindAroundWalls, TheEnergyChangesByTheTermsPowerToRoundOff) {
    const RunInputs run = testing::sharedRun(holeInAChannel());
    auto wind = std::make_shared<WindTransport>(run.cache, WindSpec{{1.0, 0.3, 0.0}});
    FluidParameters parameters;
    parameters.linear = wind;
    const FluidSystem system(*run.coefficients, parameters);
    ModalIntegrator integrator(system, IntegratorSettings{Integrator::Midpoint});
    Eigen::VectorXd v = testing::unitEnergyState(system.dimension(), 5);
    const double e0 = 0.5 * v.squaredNorm();
    const testing::EnergyBudget budget =
        testing::midpointEnergyBudget(integrator, *wind, v, 0.01, 1000);
    const double e1 = 0.5 * v.squaredNorm();
    EXPECT_LE(budget.worstStep, 1e-13);
    EXPECT_LE(budget.drift, 1e-11);
    EXPECT_LT(e1, e0) << "the wind carries the disturbance out";
    std::printf(
        "[ measured ] wind (1, 0.3) round a hole, 1000 midpoint steps: energy %.4f -> %.4f; "
        "worst step |dE - h v.Dv| %.1e E0, drift %.1e E0\n",
        e0, e1, budget.worstStep, budget.drift);
}

TEST(WindAroundWalls, WallsThatSealTheSidesOrBarTheWayAreRefusedByName) {
    // A disk of air inside the box: the wind has no side to cross.
    const RunInputs run = testing::sharedRun(testing::unitBallScene(2, 24, 10, 0));
    ASSERT_EQ(run.cache.windBase.size(), 4u);
    try {
        windBaseFlow(run.cache, WindSpec{{0.0, 1.0, 0.0}});
        FAIL() << "a sealed box took a wind";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("y component blows at the box's sides along y"),
                  std::string::npos)
            << e.what();
    }
    // A wall across the channel: air entering at x_min has no way to x_max, either way; up the
    // channel's halves it blows.
    SceneSpec barred = holeInAChannel();
    barred.domain.back() = testing::box({0.9, -1.0, 0.0}, {1.1, 2.0, 0.0}, CsgOp::Subtract);
    const RunInputs halves = testing::sharedRun(barred);
    ASSERT_EQ(halves.cache.windBase.size(), 4u);
    EXPECT_TRUE(halves.cache.windBase[0].empty());
    EXPECT_TRUE(halves.cache.windBase[1].empty());
    EXPECT_FALSE(halves.cache.windBase[2].empty());
    for (const double u : {1.0, -1.0}) {
        try {
            windBaseFlow(halves.cache, WindSpec{{u, 0.5, 0.0}});
            FAIL() << "a barred channel took a wind along x";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("let no wind blow along ") +
                                                 (u > 0.0 ? "+x" : "-x")),
                      std::string::npos)
                << e.what();
        }
    }
    EXPECT_NO_THROW(windBaseFlow(halves.cache, WindSpec{{0.0, -0.5, 0.0}}));
}

}  // namespace
}  // namespace modeflow
