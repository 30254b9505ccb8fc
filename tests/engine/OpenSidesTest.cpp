// Open sides ([grid] open; engine/README.md, "Open sides"): the air crosses them with its
// pressure and tangential velocity held at 0 there, the energy identity of the conserving
// integrators stays exact (the rotational form's open side carries no energy), a pair of opposite
// open sides lets a flow straight through, and the smoke leaves and takes in clean air.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "engine/basis/VelocityBasis.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/reference/Simulation.h"
#include "engine/reference/SmokeAdvection.h"
#include "precompute/Precompute.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/TestScenes.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {
namespace {

constexpr std::array<bool, 6> kTop{false, false, false, true, false, false};
constexpr std::array<bool, 6> kBottomAndTop{false, false, true, true, false, false};

TEST(OpenSides, TheMidpointRuleKeepsTheEnergyExactly) {
    // vᵀC(v, v) = ⟨u, ω × u⟩ = 0 whatever the sides: the open side holds the total pressure
    // p + ½|u|² at 0, so the energy it lets through is ∮(p + ½|u|²) u·n = 0.
    for (const auto& open : {kTop, kBottomAndTop}) {
        const RunInputs run = testing::sharedRun(testing::openBoxScene(open, 30));
        const FluidSystem system(*run.coefficients, FluidParameters{});
        ModalIntegrator integrator(system, IntegratorSettings{Integrator::Midpoint});
        std::mt19937 random(3);
        std::normal_distribution<double> normal;
        Eigen::VectorXd v(system.dimension());
        for (Eigen::Index k = 0; k < v.size(); ++k) v[k] = normal(random);
        const Eigen::VectorXd start = v;
        const double e0 = 0.5 * v.squaredNorm();
        double worst = 0.0;
        for (int step = 0; step < 1000; ++step) {
            integrator.step(v, 0.01);
            worst = std::max(worst, std::abs(0.5 * v.squaredNorm() - e0) / e0);
        }
        EXPECT_LE(worst, 1e-9);
        EXPECT_GT((v - start).norm(), 0.1 * start.norm()) << "the modes exchanged their energy";
        std::printf("[ measured ] open %s, 1000 midpoint steps: worst energy drift %.1e E0\n",
                    open == kTop ? "top" : "bottom and top", worst);
    }
}

TEST(OpenSides, ABoxOpenAtBothEndsLetsAFlowStraightThrough) {
    // The harmonic field of a box open at its bottom and top is the uniform upward flow: every
    // face normal to y (the open sides' included) carries the same flux, no other face any.
    const RunInputs run = testing::sharedRun(testing::openBoxScene(kBottomAndTop, 10));
    ASSERT_EQ(run.cache.velocity.harmonic, 1);
    const VelocityBasis basis(run.cache);
    Eigen::VectorXd first = Eigen::VectorXd::Zero(basis.modeCount());
    first[0] = 1.0;
    const Eigen::VectorXd flux = basis.fluxes(first);
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
    const double through = flux[Eigen::Index(
        std::find(run.cache.faces.begin(), run.cache.faces.end(), grid.faceIndex(1, 0, 0, 0)) -
        run.cache.faces.begin())];
    ASSERT_GT(std::abs(through), 0.0);
    double worst = 0.0;
    int upward = 0;
    for (std::size_t i = 0; i < run.cache.faces.size(); ++i) {
        const bool normalY = run.cache.faces[i] >= grid.faceOffset(1);
        worst = std::max(worst, std::abs(flux[Eigen::Index(i)] - (normalY ? through : 0.0)));
        upward += normalY;
    }
    EXPECT_LE(worst, 1e-10 * std::abs(through));
    EXPECT_EQ(upward, 12 * 16) << "every normal-y face, both open sides' included";
}

/// The face field of an upward flow `speed` through `grid` (its sides across y open).
std::vector<double> upwardFlow(const MacGrid& grid, double speed) {
    std::vector<double> velocity(std::size_t(grid.faceTotal()), 0.0);
    for (std::int64_t f = grid.faceOffset(1); f < grid.faceOffset(2); ++f)
        velocity[std::size_t(f)] = speed;
    return velocity;
}

TEST(OpenSides, SmokeLeavesWithoutPilingUpAndCleanAirComesIn) {
    const MacGrid open = MacGrid::fromSpec(testing::openBoxScene(kBottomAndTop, 10).grid);
    const std::vector<std::uint8_t> mask(std::size_t(open.cellCount()), 1);
    const std::vector<double> velocity = upwardFlow(open, 0.8);
    const double volume = 1.25;
    const int steps = int(std::ceil(3.0 * 1.25 / 0.8 / 0.02));  // three crossings
    for (const AdvectionScheme scheme :
         {AdvectionScheme::SemiLagrangian, AdvectionScheme::MacCormack}) {
        // A box full of smoke is flushed: clean air comes in at the bottom, the smoke leaves
        // at the top.
        const reference::SmokeAdvection chimney(open, 1, mask);
        std::vector<double> full(mask.size(), 1.0);
        for (int s = 0; s < steps; ++s) full = chimney.advect(velocity, full, 0.02, scheme);
        EXPECT_LE(chimney.mass(full), 1e-6 * volume);
        // A puff crosses the top without piling up against it.
        std::vector<double> puff = testing::gaussianBlob(open, {0.5, 0.6, 0.0}, 0.1);
        double peak = 0.0;
        for (int s = 0; s < steps; ++s) {
            puff = chimney.advect(velocity, puff, 0.02, scheme);
            for (const double value : puff) peak = std::max(peak, value);
        }
        EXPECT_LE(peak, 1.0 + 1e-12);
        EXPECT_LE(chimney.mass(puff), 1e-6);
        std::printf("[ measured ] scheme %d: %.1e of a full box left after three crossings\n",
                    int(scheme), chimney.mass(full) / volume);
    }
    // Sealed, the same field keeps its smoke: the open sides are what let it out.
    MacGrid sealed = open;
    sealed.open = {};
    const reference::SmokeAdvection box(sealed, 1, mask);
    std::vector<double> kept(mask.size(), 1.0);
    for (int s = 0; s < steps; ++s)
        kept = box.advect(velocity, kept, 0.02, AdvectionScheme::SemiLagrangian);
    EXPECT_GE(box.mass(kept), 0.99 * volume);
}

TEST(OpenSides, AJetThroughAnOpenFloorDrawsAirInAndTheTopLetsItOut) {
    // A jet through a wall: a source with a velocity over a stretch of the open floor drives the
    // air in across it; the open top lets it out, the floor beside the jet lets air in too.
    SceneSpec scene = testing::openBoxScene(kBottomAndTop, 40);
    scene.name = "jet";
    scene.simulation.dt = 0.02;
    SourceSpec jet;
    jet.shape = testing::box({0.38, -0.1, 0.0}, {0.62, 0.1, 0.0});
    jet.density = 1.0;
    jet.velocity = Vec3{0.0, 1.0, 0.0};
    scene.sources = {jet};
    const RunInputs run = testing::sharedRun(scene);
    reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
    cpu.advanceSteps(10);
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
    const std::vector<double> u = cpu.faceVelocity();
    double underJet = 0.0, top = 0.0;
    int covered = 0;
    for (int x = 0; x < grid.cells[0]; ++x) {
        const double centre = grid.cellCentre(0, x);
        if (centre > 0.38 && centre < 0.62) {
            underJet += u[std::size_t(grid.faceIndex(1, x, 0, 0))];
            ++covered;
        }
        top += u[std::size_t(grid.faceIndex(1, x, grid.cells[1], 0))] * grid.spacing[0];
    }
    ASSERT_GT(covered, 0);
    std::printf(
        "[ measured ] jet of 1 through the open floor: %.3f across the floor under it, "
        "%.3f out through the top\n",
        underJet / covered, top);
    EXPECT_GT(underJet / covered, 0.5) << "the jet drives the air in across the open floor";
    EXPECT_GT(top, 0.0) << "its air leaves through the open top";
}

TEST(OpenSides, ParticlesCarriedThroughAnOpenSideLeaveTheRun) {
    // Tracers near the top of a box open at both ends, in the flow straight through: those the
    // air carries across the top leave for good (kParticleLeft, at rest); the others stay inside.
    SceneSpec scene = testing::openBoxScene(kBottomAndTop, 10);
    scene.name = "leaving";
    scene.simulation.dt = 0.02;
    ParticleSetSpec tracers;
    tracers.region = testing::box({0.1, 0.9, 0.0}, {0.9, 1.2, 0.0});
    tracers.count = 300;
    scene.particles = {tracers};
    const RunInputs run = testing::sharedRun(scene);
    reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
    Eigen::VectorXd through = Eigen::VectorXd::Zero(cpu.velocity().size());
    through[0] = 1.0;  // the harmonic field: up at 1/√1.25
    cpu.restore(0.0, through, cpu.smoke());
    std::vector<bool> gone(300, false);
    int left = 0;
    for (int step = 0; step < 10; ++step) {
        cpu.advanceSteps(1);
        const Particles p = cpu.particles();
        ASSERT_EQ(p.size(), 300u) << "a particle that leaves keeps its place (its id)";
        left = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const double* x = &p.position[3 * i];
            if (particleLeft(x, &p.velocity[3 * i])) {
                ++left;
                gone[i] = true;
                continue;
            }
            EXPECT_FALSE(gone[i]) << "particle " << i << " came back";
            EXPECT_LE(x[1], 1.25) << "inside the box";
            EXPECT_TRUE(std::isfinite(x[0]) && std::isfinite(x[1]));
        }
    }
    // 10 steps at 0.894 carry the air 0.18 up: the tracers that started above 1.07 (43% of
    // them) are gone.
    EXPECT_GT(left, 90);
    EXPECT_LT(left, 170);
    std::printf("[ measured ] %d of 300 tracers left through the open top\n", left);
}

TEST(OpenSides, TheWallSideOfAHalfOpenAxisStaysAWall) {
    // Open at the top only: sampling reads the open side's faces but still treats the floor as a
    // wall, whatever a field holds there.
    const MacGrid grid = MacGrid::fromSpec(testing::openBoxScene(kTop, 10).grid);
    EXPECT_TRUE(grid.isWallFace(1, 0));
    EXPECT_FALSE(grid.isWallFace(1, grid.cells[1]));
    EXPECT_TRUE(grid.isWallFace(0, 0));
    EXPECT_EQ(grid.boundaryBits(), 2u << 3) << "the kernels read the sides across y";
}

}  // namespace
}  // namespace modeflow
