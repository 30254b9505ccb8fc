// Inflows ([[inflow]]; engine/README.md, "Inflows"): where an inflow's ball or box meets a side
// the air crosses, the air coming in carries its density, temperature and fuel (the ghost cells
// beyond the side, OutsideAir), on every scheme, with the conservative scheme's budget exact;
// with a velocity it drives the air in across the side; it lets air in only while it is on; and
// one that covers no fluid cell of its side is refused by name.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/core/Error.h"
#include "engine/reference/Simulation.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/simulation/OutsideAir.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/TestScenes.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {
namespace {

constexpr std::array<bool, 6> kBottomAndTop{false, false, true, true, false, false};

/// An inflow on `side` of the shape, letting in `density` and `temperature`.
InflowPatch patch(int side, const ShapeSpec& shape, double density, double temperature = 0.0) {
    InflowSpec spec;
    spec.side = side;
    spec.shape = shape;
    spec.density = density;
    spec.temperature = temperature;
    return inflowFromSpec(spec);
}

TEST(Inflows, GhostsLieAlongTheSidesAndTheFirstPatchListedWins) {
    // 8 × 6 cells over [0, 1] × [0, 0.75]: 6 ghosts along each x side, 8 along each y side.
    GridSpec spec;
    spec.resolution = {8, 6, 1};
    spec.boundsMax = {1.0, 0.75, 0.0};
    const MacGrid grid = MacGrid::fromSpec(spec);
    OutsideAir air(grid, kBottomAndTop, {0.1, 0.2, 0.0});
    EXPECT_EQ(air.ghostCount(), 2 * 6 + 2 * 8);
    EXPECT_EQ(air.ghostIndex(2, {5, 0, 0}), 12 + 5);
    EXPECT_EQ(air.ghostIndex(3, {5, 6, 0}), 20 + 5) << "the coordinate across the side unused";
    // A box over x ∈ [0.25, 0.5] (cells 2, 3) listed before a ball over x ∈ [0.3, 0.7] (2 to 5).
    const std::vector<InflowPatch> patches{
        patch(2, testing::box({0.25, -0.1, 0.0}, {0.5, 0.1, 0.0}), 1.0, 3.0),
        patch(2, testing::ball({0.5, 0.0, 0.0}, 0.2), 2.0)};
    air.setInflows(patches);
    const double expected[] = {0.1, 0.1, 1.0, 1.0, 2.0, 2.0, 0.1, 0.1};
    for (int x = 0; x < 8; ++x) {
        const std::int64_t ghost = air.ghostIndex(2, {x, 0, 0});
        EXPECT_EQ(air.value(ghost, OutsideAir::Field::Density), expected[x]) << "cell " << x;
        EXPECT_EQ(air.value(air.ghostIndex(3, {x, 0, 0}), OutsideAir::Field::Density), 0.1)
            << "the top keeps the base values";
        EXPECT_EQ(air.value(ghost, std::nullopt), 0.0) << "clean air asked for";
    }
    EXPECT_EQ(air.value(air.ghostIndex(2, {3, 0, 0}), OutsideAir::Field::Temperature), 3.0);
    EXPECT_EQ(air.value(air.ghostIndex(2, {4, 0, 0}), OutsideAir::Field::Temperature), 0.0);
    // A sample reads the ghost beyond the side it reaches farthest past, at its column.
    EXPECT_EQ(air.ghostOf({3.2, -0.3, 0.5}), air.ghostIndex(2, {3, 0, 0}));
    EXPECT_EQ(air.ghostOf({7.9, 0.1, 0.5}), air.ghostIndex(2, {7, 0, 0}));
    EXPECT_EQ(air.ghostOf({-0.2, 5.9, 0.5}), air.ghostIndex(3, {0, 0, 0})) << "clamped to the box";
    EXPECT_EQ(air.ghostOf({NAN, -0.2, 0.5}), air.ghostIndex(2, {0, 0, 0})) << "a diverged trace";
    EXPECT_DOUBLE_EQ(air.inBoxShare({3.5, 0.2, 0.5}), 0.7);
    EXPECT_DOUBLE_EQ(air.inBoxShare({3.5, 3.0, 0.5}), 1.0);
    const std::vector<float> texels = air.texels();
    ASSERT_EQ(texels.size(), 4u * 28);
    EXPECT_EQ(texels[4 * 15 + 0], 1.0f);
    EXPECT_EQ(texels[4 * 15 + 1], 3.0f);
    // Switched off, the base again.
    air.setInflows({});
    EXPECT_EQ(air.value(air.ghostIndex(2, {3, 0, 0}), OutsideAir::Field::Density), 0.1);
}

TEST(Inflows, ThePatchesAirFillsItsColumnAndNoOther) {
    // Straight up through the box: the air coming in over x ∈ [0.3, 0.6] (cells 4 to 6) carries
    // density 1 and temperature 0.5, elsewhere clean air; columns do not mix in this flow.
    const MacGrid grid = MacGrid::fromSpec(testing::openBoxScene(kBottomAndTop, 10).grid);
    const std::vector<std::uint8_t> mask(std::size_t(grid.cellCount()), 1);
    std::vector<double> velocity(std::size_t(grid.faceTotal()), 0.0);
    for (std::int64_t f = grid.faceOffset(1); f < grid.faceOffset(2); ++f)
        velocity[std::size_t(f)] = 0.8;
    const InflowPatch jet = patch(2, testing::box({0.3, -0.1, 0.0}, {0.6, 0.1, 0.0}), 1.0, 0.5);
    const int steps = int(std::ceil(3.0 * 1.25 / 0.8 / 0.02));  // three crossings
    for (const AdvectionScheme scheme :
         {AdvectionScheme::SemiLagrangian, AdvectionScheme::MacCormack,
          AdvectionScheme::Conservative}) {
        reference::SmokeAdvection chimney(grid, 1, mask);
        chimney.setInflows(std::vector<InflowPatch>{jet});
        SmokeFields fields{std::vector<double>(mask.size(), 0.0),
                           std::vector<double>(mask.size(), 0.0)};
        for (int s = 0; s < steps; ++s) chimney.step(velocity, 0.02, scheme, {}, fields);
        double column = 0.0, beside = 0.0, warm = 0.0;
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const auto c = std::size_t(grid.cellIndex(x, y, 0));
                if (x >= 4 && x <= 6) {
                    column = std::max(column, std::abs(fields.density[c] - 1.0));
                    warm = std::max(warm, std::abs(fields.temperature[c] - 0.5));
                } else {
                    beside = std::max(beside, std::abs(fields.density[c]));
                }
            }
        std::printf(
            "[ measured ] scheme %d, three crossings: the column %.1e off the inflow's "
            "density, %.1e beside it\n",
            int(scheme), column, beside);
        EXPECT_LE(column, 1e-4);
        EXPECT_LE(warm, 0.5e-4);
        EXPECT_LE(beside, 1e-12);
        // The conservative scheme's budget: what the box holds came in across its sides.
        if (scheme != AdvectionScheme::Conservative) continue;
        std::vector<double> density(mask.size(), 0.0);
        double crossed = 0.0;
        for (int s = 0; s < steps; ++s) {
            double out = 0.0;
            density =
                chimney.advect(velocity, density, 0.02, scheme, &out, OutsideAir::Field::Density);
            crossed += out;
        }
        const double held = chimney.mass(density);
        std::printf("[ measured ] conservative budget: held %.6f, came in %.6f (relative %.1e)\n",
                    held, -crossed, std::abs(held + crossed) / held);
        EXPECT_GT(held, 0.2);
        EXPECT_LE(std::abs(held + crossed), 1e-12 * held);
    }
}

TEST(Inflows, AJetThroughAnOpenFloorDrivesTheAirAndBringsItsSmoke) {
    SceneSpec scene = testing::openBoxScene(kBottomAndTop, 40);
    scene.name = "inflow_jet";
    scene.simulation.dt = 0.02;
    InflowSpec jet;
    jet.side = 2;
    jet.shape = testing::box({0.38, -0.1, 0.0}, {0.62, 0.1, 0.0});
    jet.velocity = Vec3{0.0, 1.0, 0.0};
    jet.density = 1.0;
    scene.inflows = {jet};
    const RunInputs run = testing::sharedRun(scene);
    ASSERT_EQ(run.settings.inflows.size(), 1u);
    reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
    cpu.advanceSteps(20);
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
    const std::vector<double> u = cpu.faceVelocity();
    const std::vector<double> density = cpu.smoke().density;
    double across = 0.0, floorSmoke = 0.0, besideSmoke = 0.0;
    int covered = 0;
    for (int x = 0; x < grid.cells[0]; ++x) {
        const double centre = grid.cellCentre(0, x);
        const double smoke = density[std::size_t(grid.cellIndex(x, 0, 0))];
        if (centre > 0.38 && centre < 0.62) {
            across += u[std::size_t(grid.faceIndex(1, x, 0, 0))];
            floorSmoke += smoke;
            ++covered;
        } else if (centre < 0.2 || centre > 0.8) {
            besideSmoke = std::max(besideSmoke, smoke);
        }
    }
    ASSERT_GT(covered, 0);
    std::printf(
        "[ measured ] inflow jet of 1: %.3f across the floor under it, smoke %.3f in "
        "the first row above it, at most %.1e away from it\n",
        across / covered, floorSmoke / covered, besideSmoke);
    EXPECT_GT(across / covered, 0.5) << "the jet drives the air in across the open floor";
    EXPECT_GT(floorSmoke / covered, 0.9) << "and its air arrives with the inflow's density";
    EXPECT_LT(besideSmoke, 0.05) << "clean air elsewhere";
}

TEST(Inflows, AnInflowLetsSmokeInOnlyWhileItIsOn) {
    // A rake upstream of a wind, on from t = 0.2 to 0.4: before, none of its smoke; while on,
    // smoke; after, its smoke blown on and out.
    SceneSpec scene = testing::gridScene({16, 8, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2);
    scene.name = "inflow_rake";
    scene.basis.velocityModes = {{1, 20}};
    scene.basis.scalarModes = 0;
    scene.simulation.dt = 0.02;
    WindSpec wind;
    wind.velocity = {2.0, 0.0, 0.0};
    scene.wind = wind;
    InflowSpec rake;
    rake.side = 0;
    rake.shape = testing::ball({0.0, 0.5, 0.0}, 0.2);
    rake.density = 1.0;
    rake.start = 0.2;
    rake.end = 0.4;
    scene.inflows = {rake};
    const RunInputs run = testing::sharedRun(scene);
    reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
    const auto held = [&] {
        double sum = 0.0;
        for (const double value : cpu.smoke().density) sum += value;
        return sum;
    };
    cpu.advanceSteps(10);
    EXPECT_EQ(held(), 0.0) << "nothing before it starts";
    cpu.advanceSteps(10);
    const double whileOn = held();
    EXPECT_GT(whileOn, 1.0);
    cpu.advanceSteps(100);  // 2 s at 2: its last smoke 1.6 past the outlet
    std::printf("[ measured ] timed rake: %.3f held while on, %.1e a box's crossing after\n",
                whileOn, held());
    EXPECT_LT(held(), 1e-3 * whileOn);
}

TEST(Inflows, OneThatCoversNoFluidCellOfItsSideIsRefused) {
    SceneSpec scene = testing::openBoxScene(kBottomAndTop, 10);
    scene.name = "inflow_missing";
    InflowSpec pinhole;
    pinhole.side = 2;
    // Between the centres 0.375 and 0.458 of cells 4 and 5.
    pinhole.shape = testing::ball({0.41, 0.0, 0.0}, 0.02);
    scene.inflows = {pinhole};
    const RunInputs run = testing::sharedRun(scene);
    try {
        reference::Simulation cpu(run.cache, *run.coefficients, run.settings, run.smokeMask);
        FAIL() << "a pinhole inflow was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "[[inflow]] #1 (y_min): its shape covers the centre of no fluid smoke "
                      "cell's face on that side"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace modeflow
