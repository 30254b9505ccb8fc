/// @file NoSlipWindTest.cpp
/// A wind round no-slip [[domain]] walls (engine/README.md, "Wind"): viscosity acts on the whole
/// velocity B + Ψv, so the held flow's slip along a no-slip wall relaxes the modes toward its
/// Stokes correction c (BasisCache::windStokes). In a channel the air then takes Poiseuille's
/// profile; free-slip walls leave the potential flow as it is; a run reaches c.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/core/MacGrid.h"
#include "engine/reference/Simulation.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/simulation/WindTransport.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// [0, 4] × [0, 1] in 64 × 16 cells; the domain box reaches past the grid, so its walls are the
/// grid's sides, [[domain]] walls all the same (the cache holds held flows).
SceneSpec channel(WallKind wall, int modes, bool periodic = false) {
    SceneSpec scene = testing::gridScene({64, 16, 1}, {0.0, 0.0, 0.0}, {4.0, 1.0, 0.0}, 2);
    scene.grid.periodic = {periodic, false, false};
    scene.domain = {testing::box({-1.0, -1.0, 0.0}, {5.0, 2.0, 0.0})};
    scene.basis.wall = wall;
    scene.basis.velocityModes = {{1, modes}};
    scene.basis.scalarModes = 0;
    return scene;
}

/// The air's velocity along x across the channel's middle (or the x-normal faces of `column`),
/// row by row, for modal amplitudes `v` in a unit wind along x.
std::vector<double> middleProfile(const BasisCache& cache, const Eigen::VectorXd& v,
                                  int column = -1) {
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    const std::vector<double> modal = reference::reconstructFaceField(cache, v);
    std::vector<double> profile;
    for (int y = 0; y < grid.cells[1]; ++y) {
        const auto face =
            std::size_t(grid.faceIndex(0, column < 0 ? grid.cells[0] / 2 : column, y, 0));
        profile.push_back(cache.windBase[0][face] + modal[face]);
    }
    return profile;
}

/// The worst difference of `profile` from Poiseuille's 6 y (1 − y) at the rows' centres.
double offPoiseuille(const std::vector<double>& profile) {
    double worst = 0.0;
    for (std::size_t j = 0; j < profile.size(); ++j) {
        const double y = (double(j) + 0.5) / double(profile.size());
        worst = std::max(worst, std::abs(profile[j] - 6.0 * y * (1.0 - y)));
    }
    return worst;
}

Eigen::VectorXd stokesOf(const BasisCache& cache, int flow) {
    const std::vector<double>& c = cache.windStokes[std::size_t(flow)];
    return Eigen::Map<const Eigen::VectorXd>(c.data(), Eigen::Index(c.size()));
}

/// The profile's mean, the flux through the middle over the channel's height.
double meanOf(const std::vector<double>& profile) {
    double mean = 0.0;
    for (const double u : profile) mean += u / double(profile.size());
    return mean;
}

TEST(NoSlipWind, APeriodicNoSlipChannelTakesPoiseuillesProfile) {
    // Along a periodic axis the held flow is the plug U, and its Stokes correction the
    // parabola's difference from it, flux held (a pressure drop drives the channel). Two
    // columns of thin cells: the 16 lowest modes are the profiles u_x(y), all of them, so the
    // correction is the grid's whole Stokes flow.
    SceneSpec scene = channel(WallKind::NoSlip, 16, true);
    scene.grid.resolution = {2, 16, 1};
    scene.grid.boundsMax = {0.0625, 1.0, 0.0};
    const RunInputs run = testing::sharedRun(scene);
    ASSERT_EQ(run.cache.windStokes.size(), 4u);
    const std::vector<double> profile = middleProfile(run.cache, stokesOf(run.cache, 0), 0);
    const double off = offPoiseuille(profile);
    std::printf(
        "[ measured ] periodic no-slip channel 2 x 16, 16 modes: centre %.4f (Poiseuille "
        "1.4941 at the rows' centres), wall row %.4f (0.1816), worst off the profile %.2e\n",
        0.5 * (profile[7] + profile[8]), profile[0], off);
    EXPECT_LT(off, 0.02);
    EXPECT_NEAR(meanOf(profile), 1.0, 1e-10);
}

TEST(NoSlipWind, AClosedNoSlipChannelSlowsAtItsWallsAndAFreeSlipOneKeepsThePlugFlow) {
    // Between an inflow and an outflow held plug the middle tends to the parabola as the modes
    // resolve the ends (a correction that vanishes at both: slow in a truncated basis).
    double previous = 1.0;
    for (const int modes : {40, 120}) {
        const RunInputs run = testing::sharedRun(channel(WallKind::NoSlip, modes));
        ASSERT_EQ(run.cache.windStokes.size(), 4u);
        const std::vector<double> profile = middleProfile(run.cache, stokesOf(run.cache, 0));
        const double centre = 0.5 * (profile[7] + profile[8]), off = offPoiseuille(profile);
        std::printf(
            "[ measured ] no-slip channel 64 x 16, %d modes: centre %.4f, wall row %.4f, worst "
            "off Poiseuille %.2e\n",
            modes, centre, profile[0], off);
        EXPECT_LT(off, previous) << "more modes come closer";
        previous = off;
        EXPECT_NEAR(centre, 1.5, 0.08);
        EXPECT_LT(profile[0], 0.9);
        EXPECT_NEAR(meanOf(profile), 1.0, 1e-10) << "the correction carries no flux";
    }
    const RunInputs slip = testing::sharedRun(channel(WallKind::FreeSlip, 40));
    const RunInputs stuck = testing::sharedRun(channel(WallKind::NoSlip, 40));
    for (int flow = 0; flow < 4; ++flow) {
        const double free = stokesOf(slip.cache, flow).cwiseAbs().maxCoeff();
        EXPECT_LE(free, 1e-10 * stokesOf(stuck.cache, flow).cwiseAbs().maxCoeff()) << flow;
    }
}

TEST(NoSlipWind, RoundANoSlipHoleTheAirSlowsAtItsWall) {
    // A hole of radius 0.17 at (1, 0.5) in [0, 2] × [0, 1], 64 × 32 cells: the potential flow
    // runs about twice the wind over its crown; its Stokes flow slows there, the more so the
    // nearer the wall, and a free-slip hole keeps it.
    const auto hole = [](WallKind wall) {
        SceneSpec scene = testing::gridScene({64, 32, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2);
        scene.domain = {testing::box({-1.0, -1.0, 0.0}, {3.0, 2.0, 0.0}),
                        testing::ball({1.0, 0.5, 0.0}, 0.17, CsgOp::Subtract)};
        scene.basis.wall = wall;
        scene.basis.velocityModes = {{1, 80}};
        scene.basis.scalarModes = 0;
        return testing::sharedRun(scene);
    };
    const RunInputs stuck = hole(WallKind::NoSlip), slip = hole(WallKind::FreeSlip);
    const MacGrid grid = MacGrid::fromSpec(stuck.cache.grid);
    const std::vector<double> modal =
        reference::reconstructFaceField(stuck.cache, stokesOf(stuck.cache, 0));
    // The x-normal faces over the crown (x = 1), from the first above the hole (y = 0.67) up.
    double nearest = 0.0, nearestHeld = 0.0, further = 0.0, furtherHeld = 0.0;
    for (int y = 16; y < grid.cells[1]; ++y) {
        const auto face = std::size_t(grid.faceIndex(0, 32, y, 0));
        if (stuck.cache.cellFraction[std::size_t(grid.cellIndex(31, y, 0))] < 1.0) continue;
        if (nearestHeld == 0.0) {
            nearestHeld = stuck.cache.windBase[0][face];
            nearest = nearestHeld + modal[face];
        } else if (furtherHeld == 0.0) {
            furtherHeld = stuck.cache.windBase[0][face];
            further = furtherHeld + modal[face];
        }
    }
    std::printf(
        "[ measured ] no-slip hole in 64 x 32, 80 modes, over the crown: the first whole row "
        "%.3f U (potential flow %.3f U), the next %.3f U (%.3f U)\n",
        nearest, nearestHeld, further, furtherHeld);
    EXPECT_GT(nearestHeld, 1.6);
    EXPECT_LT(nearest, 0.8 * nearestHeld);
    EXPECT_LT(nearest / nearestHeld, further / furtherHeld) << "slowest at the wall";
    const double free = stokesOf(slip.cache, 0).cwiseAbs().maxCoeff(),
                 held = stokesOf(stuck.cache, 0).cwiseAbs().maxCoeff();
    std::printf("[ measured ] free-slip hole: largest Stokes amplitude %.1e (no-slip %.1e)\n", free,
                held);
    EXPECT_LE(free, 1e-6 * held);
}

TEST(NoSlipWind, AViscousRunRelaxesTheModesToTheStokesCorrection) {
    // A slow wind (Re = U H / ν = 0.01): the run's modes settle on U c, to O(Re).
    SceneSpec scene = channel(WallKind::NoSlip, 40);
    scene.wind = WindSpec{{-0.01, 0.0, 0.0}};
    scene.simulation.viscosity = 1.0;
    scene.simulation.dt = 0.01;
    const RunInputs run = testing::sharedRun(scene);
    reference::Simulation simulation(run.cache, *run.coefficients, run.settings, run.smokeMask);
    for (int frame = 0; frame < 10; ++frame) simulation.advanceFrame();
    const Eigen::VectorXd expected = 0.01 * stokesOf(run.cache, 1);  // along −x
    const double gap = (simulation.velocity() - expected).norm() / expected.norm();
    std::printf("[ measured ] Re = 0.01 run against U c, 40 modes: relative difference %.2e\n",
                gap);
    EXPECT_GT(expected.norm(), 1e-4);
    EXPECT_LE(gap, 0.05);
    // Without viscosity nothing pulls them: a still channel stays still.
    scene.simulation.viscosity = 0.0;
    const RunInputs inviscid = testing::sharedRun(scene);
    reference::Simulation still(inviscid.cache, *inviscid.coefficients, inviscid.settings,
                                inviscid.smokeMask);
    still.advanceFrame();
    EXPECT_EQ(still.velocity().norm(), 0.0);
}

}  // namespace
}  // namespace modeflow
