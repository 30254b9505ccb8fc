/// @file SmokeDisplacementTest.cpp
/// Smoke pushed out of solids (engine/simulation/SmokeDisplacement.h): the rule on the CPU
/// reference alone, with no advection — no smoke inside a solid, none carried through a thin
/// fast plate, the smoke conserved, across a periodic seam too — and the device's stages against
/// it.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/device/SmokeDisplacement.h"
#include "engine/device/SmokeState.h"
#include "engine/reference/SmokeDisplacement.h"
#include "engine/simulation/SmokeDisplacement.h"
#include "engine/vulkan/CommandSequence.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/TestSolids.h"
#include "tests/support/ThrownMessage.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

/// The unit box [0, 1]^dim in n cells a side.
MacGrid unitGrid(int dim, int n, bool periodic = false) {
    MacGrid grid;
    grid.dim = dim;
    for (int a = 0; a < dim; ++a) {
        grid.cells[a] = n;
        grid.spacing[a] = 1.0 / n;
        grid.periodic[a] = periodic;
    }
    return grid;
}

MovingObstacle ball(double radius, std::vector<std::pair<double, Vec3>> path) {
    ObstacleSpec spec;
    spec.radius = radius;
    spec.path = std::move(path);
    return MovingObstacle{spec};
}

MovingObstacle box(const Vec3& halfSize, std::vector<std::pair<double, Vec3>> path) {
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Box;
    spec.halfSize = halfSize;
    spec.path = std::move(path);
    return MovingObstacle{spec};
}

/// Whether any of `solids` covers the centre of `cell` at time t.
bool coveredAt(const MacGrid& grid, const std::vector<MovingObstacle>& solids, std::int64_t cell,
               double t) {
    const int x = int(cell % grid.cells[0]), y = int(cell / grid.cells[0] % grid.cells[1]),
              z = int(cell / (std::int64_t(grid.cells[0]) * grid.cells[1]));
    const Vec3 centre = testing::cellCentre(grid, x, y, z);
    for (const MovingObstacle& solid : solids)
        if (solid.covers(centre, solid.poseAt(t), grid)) return true;
    return false;
}

/// The largest value among the cells the solids cover at t.
double maxCovered(const MacGrid& grid, const std::vector<MovingObstacle>& solids,
                  const std::vector<double>& field, double t) {
    double most = 0.0;
    for (std::int64_t c = 0; c < grid.cellCount(); ++c)
        if (coveredAt(grid, solids, c, t)) most = std::max(most, std::abs(field[std::size_t(c)]));
    return most;
}

double total(const std::vector<double>& field) {
    return std::accumulate(field.begin(), field.end(), 0.0);
}

/// `value` in every cell the solids leave free at t (temperature: twice the density).
SmokeFields smokeOutside(const MacGrid& grid, const std::vector<MovingObstacle>& solids,
                         double value, double t) {
    SmokeFields fields{std::vector<double>(std::size_t(grid.cellCount()), 0.0), {}};
    for (std::int64_t c = 0; c < grid.cellCount(); ++c)
        if (!coveredAt(grid, solids, c, t)) fields.density[std::size_t(c)] = value;
    fields.temperature = fields.density;
    for (double& v : fields.temperature) v *= 2.0;
    return fields;
}

TEST(SmokeDisplacement, ABallCrossingSmokeLeavesNoneInsideAndKeepsItAll) {
    // The 32³ box full of smoke at 0.1, a ball of radius 0.15 crossing it at 1.5 cells a step
    // (three substeps): nothing inside the ball after any step, the smoke piled up in front of it,
    // and none lost.
    const MacGrid grid = unitGrid(3, 32);
    const std::vector<MovingObstacle> solids{
        ball(0.15, {{0.0, {0.2, 0.5, 0.5}}, {1.0, {0.8, 0.5, 0.5}}})};
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    reference::SmokeDisplacement displacement(grid, fluid);
    SmokeFields fields = smokeOutside(grid, solids, 0.1, 0.0);
    const double density = total(fields.density), temperature = total(fields.temperature);
    const double dt = 0.075;  // 1.44 cells
    EXPECT_EQ(displacementSubsteps(solids, 0.0, dt, grid), 3);
    for (int step = 0; step < 12; ++step) {
        displacement.step(solids, step * dt, dt, fields);
        const double t = (step + 1) * dt;
        ASSERT_EQ(maxCovered(grid, solids, fields.density, t), 0.0) << "step " << step;
        ASSERT_EQ(maxCovered(grid, solids, fields.temperature, t), 0.0) << "step " << step;
        ASSERT_NEAR(total(fields.density), density, 1e-12 * density) << "step " << step;
        ASSERT_NEAR(total(fields.temperature), temperature, 1e-12 * temperature);
    }
    // Pushed, not spread thin: cells ahead of the ball hold more than they started with.
    EXPECT_GT(*std::max_element(fields.density.begin(), fields.density.end()), 0.2);
}

TEST(SmokeDisplacement, AThinFastPlateLeavesNoSmokeBehindIt) {
    // A plate 0.9 cells thick sweeps along x at two cells a step (four substeps) through a layer
    // of smoke: everything it swept is empty behind it, and the layer is in front of it.
    const int n = 32;
    const MacGrid grid = unitGrid(3, n);
    const double h = 1.0 / n, dt = 0.01, speed = 2.0 * h / dt;
    const Vec3 start{0.1 + 0.1 * h, 0.5, 0.5};
    const std::vector<MovingObstacle> solids{
        box({0.45 * h, 0.25, 0.25}, {{0.0, start}, {1.0, {start[0] + speed, 0.5, 0.5}}})};
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    reference::SmokeDisplacement displacement(grid, fluid);
    SmokeFields fields{std::vector<double>(std::size_t(grid.cellCount()), 0.0), {}};
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 12; x < 20; ++x)
                fields.density[std::size_t(grid.cellIndex(x, y, z))] = 1.0;
    fields.temperature = fields.density;
    const double before = total(fields.density);
    EXPECT_EQ(displacementSubsteps(solids, 0.0, dt, grid), 4);
    const int steps = 12;  // the plate ends at x ≈ 0.85
    for (int step = 0; step < steps; ++step) displacement.step(solids, step * dt, dt, fields);
    const double plateX = solids[0].centreAt(steps * dt)[0];
    ASSERT_GT(plateX, 0.8);
    double behind = 0.0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const Vec3 c = testing::cellCentre(grid, x, y, z);
                // Swept: inside the plate's cross-section, between its start and where it is.
                const bool swept = std::abs(c[1] - 0.5) < 0.25 - h &&
                                   std::abs(c[2] - 0.5) < 0.25 - h && c[0] < plateX - h;
                if (swept) behind += fields.density[std::size_t(grid.cellIndex(x, y, z))];
            }
    EXPECT_EQ(behind, 0.0) << "smoke carried through the plate";
    EXPECT_NEAR(total(fields.density), before, 1e-12 * before);
}

TEST(SmokeDisplacement, SmokeOnAPeriodicSeamIsPushedAcrossIt) {
    // A ball crossing the seam of a periodic square: it covers both ends at once, and the smoke
    // it meets there goes on ahead of it, on the other side.
    const MacGrid grid = unitGrid(2, 32, true);
    const std::vector<MovingObstacle> solids{
        ball(0.12, {{0.0, {0.85, 0.5, 0.0}}, {1.0, {1.25, 0.5, 0.0}}})};
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    reference::SmokeDisplacement displacement(grid, fluid);
    SmokeFields fields = smokeOutside(grid, solids, 0.3, 0.0);
    const double before = total(fields.density);
    const double dt = 0.05;
    for (int step = 0; step < 20; ++step) {
        displacement.step(solids, step * dt, dt, fields);
        ASSERT_EQ(maxCovered(grid, solids, fields.density, (step + 1) * dt), 0.0) << step;
    }
    EXPECT_NEAR(total(fields.density), before, 1e-12 * before);
    // The ball ends at x = 0.25 (past the seam): the cell ahead of it holds the pushed smoke.
    EXPECT_GT(fields.density[std::size_t(grid.cellIndex(int((0.25 + 0.12) * 32) + 1, 16, 0))], 0.3);
}

TEST(SmokeDisplacement, ASolidLengthsAwayRoundAPeriodicAxisCoversWhereItWraps) {
    // A path that has gone round the periodic square five times: the box of cells it may cover
    // is where its centre wraps to, and the smoke there is still pushed out.
    const MacGrid grid = unitGrid(2, 32, true);
    const std::vector<MovingObstacle> solids{
        ball(0.12, {{0.0, {5.85, -4.5, 0.0}}, {1.0, {6.25, -4.5, 0.0}}})};
    const std::vector<MovingObstacle> wrapped{
        ball(0.12, {{0.0, {0.85, 0.5, 0.0}}, {1.0, {1.25, 0.5, 0.0}}})};
    for (const double t : {0.0, 0.4, 0.9}) {
        const std::vector<ObstaclePose> far{solids[0].poseAt(t)}, near{wrapped[0].poseAt(t)};
        const CellBox a = displacementBox(solids, far, grid),
                      b = displacementBox(wrapped, near, grid);
        for (int axis = 0; axis < 2; ++axis) {
            EXPECT_EQ(grid.wrap(axis, a.first[axis]), grid.wrap(axis, b.first[axis])) << t;
            EXPECT_EQ(a.count[axis], b.count[axis]) << t;
        }
    }
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    reference::SmokeDisplacement displacement(grid, fluid);
    SmokeFields fields = smokeOutside(grid, solids, 0.3, 0.0);
    const double before = total(fields.density);
    for (int step = 0; step < 10; ++step) {
        displacement.step(solids, step * 0.05, 0.05, fields);
        ASSERT_EQ(maxCovered(grid, solids, fields.density, (step + 1) * 0.05), 0.0) << step;
    }
    EXPECT_NEAR(total(fields.density), before, 1e-12 * before);
}

TEST(SmokeDisplacement, ASweptBoxHoldsEachStepsBoxAndNoLaterOne) {
    // What a kept step records its solids' correction over (engine/device/Simulation.h): the
    // box of 8 steps holds each of those steps' boxes and not the box two steps after them; round
    // a periodic axis too, where the path wraps.
    for (const bool periodic : {false, true}) {
        SCOPED_TRACE(periodic ? "periodic" : "walls");
        const MacGrid grid = unitGrid(2, 32, periodic);
        const std::vector<MovingObstacle> solids{
            ball(0.1, {{0.0, {0.2, 0.5, 0.0}}, {1.0, {1.2, 0.5, 0.0}}}),
            box({0.05, 0.1, 0.0}, {{0.0, {0.5, 0.3, 0.0}}, {1.0, {0.5, 0.4, 0.0}}})};
        const double t = periodic ? 0.6 : 0.1, dt = 0.02;  // periodic: its box wraps
        const CellBox swept = sweptDisplacementBox(solids, t, dt, 8, grid);
        const auto boxAt = [&](double time) {
            const std::vector<ObstaclePose> poses{solids[0].poseAt(time), solids[1].poseAt(time)};
            return displacementBox(solids, poses, grid);
        };
        for (int s = 0; s < 8; ++s) EXPECT_TRUE(boxContains(swept, boxAt(t + s * dt), grid)) << s;
        EXPECT_FALSE(boxContains(swept, boxAt(t + 10 * dt), grid));
        EXPECT_TRUE(boxContains(swept, swept, grid));
        EXPECT_TRUE(boxContains(swept, CellBox{}, grid)) << "an empty box lies in any";
    }
    // Along a periodic axis a box going round holds one that starts past the seam.
    const MacGrid grid = unitGrid(2, 32, true);
    const CellBox round{{30, 4, 0}, {6, 5, 1}}, past{{1, 5, 0}, {3, 2, 1}},
        beyond{{2, 5, 0}, {3, 2, 1}};
    EXPECT_TRUE(boxContains(round, past, grid));
    EXPECT_FALSE(boxContains(round, beyond, grid));
}

TEST(SmokeDisplacement, AStillSolidPushesSmokeThatReachedItOutward) {
    // Smoke in the outer cells of a still ball (as advection leaves it) goes to the cells beside
    // them, outward; the outside of the ball gains exactly what the inside held.
    const MacGrid grid = unitGrid(2, 40);
    const std::vector<MovingObstacle> solids{ball(0.2, {{0.0, {0.5, 0.5, 0.0}}})};
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    SmokeFields fields{std::vector<double>(std::size_t(grid.cellCount()), 0.0), {}};
    for (std::int64_t c = 0; c < grid.cellCount(); ++c) {
        const int x = int(c % 40), y = int(c / 40);
        const Vec3 p = testing::cellCentre(grid, x, y, 0);
        const double r = std::hypot(p[0] - 0.5, p[1] - 0.5);
        // Within 0.6 cells of the surface: a free cell lies beside each.
        if (r <= 0.2 && r > 0.2 - 0.6 / 40) fields.density[std::size_t(c)] = 1.0;
    }
    fields.temperature = fields.density;
    const double inside = total(fields.density);
    reference::SmokeDisplacement(grid, fluid).step(solids, 0.0, 0.01, fields);
    EXPECT_EQ(maxCovered(grid, solids, fields.density, 0.01), 0.0);
    EXPECT_NEAR(total(fields.density), inside, 1e-12 * inside);
    for (std::int64_t c = 0; c < grid.cellCount(); ++c) {
        if (fields.density[std::size_t(c)] == 0.0) continue;
        const Vec3 p = testing::cellCentre(grid, int(c % 40), int(c / 40), 0);
        EXPECT_LE(std::hypot(p[0] - 0.5, p[1] - 0.5), 0.2 + 1.5 / 40) << "pushed inward or far";
    }
}

TEST(SmokeDisplacement, SmokeWithNowhereToGoIsRemoved) {
    // A ball placed over smoke: its outer layer is pushed out, what lies deeper (no free cell
    // beside it) is removed, and nothing stays inside.
    const MacGrid grid = unitGrid(2, 32);
    const std::vector<MovingObstacle> solids{ball(0.25, {{0.0, {0.5, 0.5, 0.0}}})};
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    SmokeFields fields{std::vector<double>(std::size_t(grid.cellCount()), 1.0), {}};
    fields.temperature = fields.density;
    const double before = total(fields.density);
    reference::SmokeDisplacement(grid, fluid).step(solids, 0.0, 0.01, fields);
    EXPECT_EQ(maxCovered(grid, solids, fields.density, 0.01), 0.0);
    const double covered = M_PI * 0.25 * 0.25 * 32 * 32;  // cells, about
    EXPECT_LT(total(fields.density), before - 0.5 * covered);
    EXPECT_GT(total(fields.density), before - covered);
}

TEST(SmokeDisplacement, SolidsTooFastForTheSmokeAreRefusedNamingThem) {
    const MacGrid grid = unitGrid(3, 32);
    // 40 cells a step: more than the 32 the substeps follow.
    const std::vector<MovingObstacle> solids{
        ball(0.1, {{0.0, {0.5, 0.5, 0.5}}}),
        ball(0.1, {{0.0, {0.1, 0.5, 0.5}}, {0.1, {0.1 + 40.0 / 32.0 * 10.0, 0.5, 0.5}}})};
    const std::string message =
        testing::thrownMessage([&] { requireDisplaceableMotion(solids, 0.01, grid); });
    EXPECT_NE(message.find("obstacle #2"), std::string::npos) << message;
    EXPECT_NE(message.find("lower dt"), std::string::npos) << message;
    EXPECT_NO_THROW(requireDisplaceableMotion(solids, 0.007, grid));
    // A turning one: its rim's speed counts.
    ObstacleSpec paddle;
    paddle.shape = ObstacleShape::Box;
    paddle.halfSize = {0.4, 0.02, 0.1};
    paddle.path = {{0.0, {0.5, 0.5, 0.5}}};
    paddle.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {1.0, {0.0, 0.0, 1.0}, 36000.0}};
    EXPECT_THROW(
        requireDisplaceableMotion(std::vector<MovingObstacle>{MovingObstacle{paddle}}, 0.01, grid),
        Error);
}

/// Random smoke in the free cells at t = 0.
SmokeFields randomSmoke(const MacGrid& grid, const std::vector<MovingObstacle>& solids,
                        std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> value(0.0, 1.0);
    SmokeFields fields{std::vector<double>(std::size_t(grid.cellCount()), 0.0),
                       std::vector<double>(std::size_t(grid.cellCount()), 0.0)};
    for (std::int64_t c = 0; c < grid.cellCount(); ++c) {
        if (coveredAt(grid, solids, c, 0.0)) continue;
        fields.density[std::size_t(c)] = value(random);
        fields.temperature[std::size_t(c)] = value(random);
    }
    return fields;
}

class SmokeDisplacementKernelTest : public testing::VulkanTest {};

TEST_P(SmokeDisplacementKernelTest, DeviceEqualsTheCpuReference) {
    // A ball and a turning box in a walled 3D box, a capsule across the seams of a box periodic
    // sideways, a turning mesh, a small ball crossing six cells a step, a box across the seams
    // of a periodic 3D box, a ball across the seam of a
    // periodic 2D square, and two balls far apart in a 3D box (covered box by box), several
    // substeps a step, six steps each.
    struct Case {
        MacGrid grid;
        std::vector<MovingObstacle> solids;
    };
    ObstacleSpec paddle;
    paddle.shape = ObstacleShape::Box;
    paddle.halfSize = {0.2, 0.03, 0.15};
    paddle.path = {{0.0, {0.31, 0.52, 0.47}}};
    paddle.rotation = {{0.0, {0.0, 0.0, 1.0}, 3.0}, {1.0, {0.0, 0.0, 1.0}, 723.0}};
    // A mesh's lattice (an L) turning fast about a tilted axis while it crosses the box.
    ObstacleSpec turning;
    turning.shape = ObstacleShape::Mesh;
    turning.path = {{0.0, {0.4, 0.45, 0.5}}, {1.0, {0.7, 0.55, 0.45}}};
    turning.rotation = {{0.0, {0.3, 0.2, 1.0}, 0.0}, {1.0, {0.3, 0.2, 1.0}, 900.0}};
    MovingObstacle mesh{turning};
    mesh.levelSet = testing::lShapedLattice();
    ObstacleSpec seam;
    seam.shape = ObstacleShape::Box;
    seam.halfSize = {0.2, 0.05, 0.1};
    seam.path = {{0.0, {0.95, 0.9, 0.05}}, {1.0, {1.3, 1.2, -0.2}}};
    seam.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {1.0, {0.0, 0.0, 1.0}, 900.0}};
    // A capsule turning about a tilted axis across the seams of a box periodic along y and z
    // alone (each solid's span of a line of cells along x is found by its shape there).
    ObstacleSpec capsule;
    capsule.shape = ObstacleShape::Capsule;
    capsule.radius = 0.07;
    capsule.axis = {0.18, 0.05, 0.0};
    capsule.path = {{0.0, {0.45, 0.92, 0.06}}, {1.0, {0.6, 1.3, -0.3}}};
    capsule.rotation = {{0.0, {0.2, 1.0, 0.4}, 10.0}, {1.0, {0.2, 1.0, 0.4}, 700.0}};
    MacGrid sidewaysPeriodic = unitGrid(3, 22);
    sidewaysPeriodic.periodic = {false, true, true};
    const std::vector<Case> cases{
        {unitGrid(3, 24),
         {ball(0.17, {{0.0, {0.71, 0.33, 0.52}}, {1.0, {0.21, 0.71, 0.48}}}),
          MovingObstacle{paddle}}},
        {sidewaysPeriodic, {MovingObstacle{capsule}}},
        {unitGrid(3, 24), {mesh}},
        // A small ball crossing six cells a step, there and back.
        {unitGrid(3, 24),
         {ball(0.08,
               {{0.0, {0.12, 0.5, 0.45}}, {0.12, {0.88, 0.55, 0.5}}, {0.24, {0.12, 0.5, 0.45}}})}},
        // Across the periodic seams of a 3D torus, turning.
        {unitGrid(3, 20, true), {MovingObstacle{seam}}},
        {unitGrid(2, 40, true), {ball(0.13, {{0.0, {0.83, 0.47, 0.0}}, {1.0, {2.03, 0.62, 0.0}}})}},
        // Two balls in far corners, overlapping at the end: a box each, then one.
        {unitGrid(3, 24),
         {ball(0.1, {{0.0, {0.15, 0.15, 0.2}}, {1.0, {0.9, 0.8, 0.5}}}),
          ball(0.12, {{0.0, {0.82, 0.81, 0.77}}, {1.0, {0.4, 0.6, 0.55}}})}}};
    for (const Case& c : cases) {
        const std::vector<std::uint8_t> fluid(std::size_t(c.grid.cellCount()), 1);
        SmokeFields cpu = randomSmoke(c.grid, c.solids, 7);
        device::SmokeState state(context(), c.grid, 1, fluid);
        state.upload(std::vector<float>(cpu.density.begin(), cpu.density.end()),
                     std::vector<float>(cpu.temperature.begin(), cpu.temperature.end()));
        reference::SmokeDisplacement reference(c.grid, fluid);
        device::SmokeDisplacement displacement(context(), state);
        const double dt = 0.04;
        for (int step = 0; step < 6; ++step) {
            reference.step(c.solids, step * dt, dt, cpu);
            vulkan::CommandSequence sequence(context());
            displacement.record(sequence, state, c.solids, step * dt, dt);
            sequence.submitAndWait();
        }
        EXPECT_GT(displacementSubsteps(c.solids, 0.0, dt, c.grid), 1);
        if (c.solids.size() == 2 && c.solids[1].spec.shape == ObstacleShape::Ball) {
            const std::vector<ObstaclePose> start{c.solids[0].poseAt(0.0), c.solids[1].poseAt(0.0)};
            EXPECT_EQ(displacementBoxes(c.solids, start, c.grid).size(), 2u) << "a box each";
        }
        std::vector<float> density(cpu.density.size()), temperature(density.size());
        state.download(density, temperature);
        double worst = 0.0;
        for (std::size_t i = 0; i < density.size(); ++i) {
            worst = std::max(worst, std::abs(density[i] - cpu.density[i]));
            worst = std::max(worst, std::abs(temperature[i] - cpu.temperature[i]));
        }
        EXPECT_LE(worst, 1e-5) << c.grid.dim << "D";
        EXPECT_EQ(maxCovered(c.grid, c.solids, std::vector<double>(density.begin(), density.end()),
                             6 * dt),
                  0.0);
    }
    expectNoValidationMessages();
}

TEST_P(SmokeDisplacementKernelTest, FuelInCellsWithoutSmokeIsPushedToo) {
    // The device pushes only cells holding something: with fire, a cell holding fuel and no
    // smoke must still be pushed (and one holding smoke and no fuel). Smoke in the left half of
    // the box, fuel in the right half, a ball sweeping across both.
    const MacGrid grid = unitGrid(3, 20);
    const std::vector<MovingObstacle> solids{
        ball(0.15, {{0.0, {0.2, 0.45, 0.5}}, {1.0, {0.85, 0.55, 0.5}}})};
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    SmokeFields cpu = randomSmoke(grid, solids, 11);
    cpu.fuel.assign(cpu.density.size(), 0.0);
    for (std::int64_t c = 0; c < grid.cellCount(); ++c) {
        const auto i = std::size_t(c);
        if (c % grid.cells[0] >= grid.cells[0] / 2) {
            cpu.fuel[i] = cpu.density[i] + 0.25 * cpu.temperature[i];
            cpu.density[i] = cpu.temperature[i] = 0.0;
        }
    }
    const auto floats = [](const std::vector<double>& v) {
        return std::vector<float>(v.begin(), v.end());
    };
    device::SmokeState state(context(), grid, 1, fluid, true);
    state.upload(floats(cpu.density), floats(cpu.temperature));
    state.upload(floats(cpu.fuel), std::vector<float>(cpu.fuel.size(), 0.0f),
                 device::SmokePair::Fuel);
    cpu.flame.assign(cpu.fuel.size(), 0.0);
    const double fuelBefore = total(cpu.fuel);
    reference::SmokeDisplacement reference(grid, fluid);
    device::SmokeDisplacement displacement(context(), state);
    const double dt = 0.05;
    for (int step = 0; step < 20; ++step) {
        reference.step(solids, step * dt, dt, cpu);
        vulkan::CommandSequence sequence(context());
        displacement.record(sequence, state, solids, step * dt, dt);
        sequence.submitAndWait();
    }
    std::vector<float> density(cpu.density.size()), temperature(density.size()),
        fuel(density.size()), flame(density.size());
    state.download(density, temperature);
    state.download(fuel, flame, device::SmokePair::Fuel);
    double worst = 0.0;
    for (std::size_t i = 0; i < density.size(); ++i)
        worst = std::max({worst, std::abs(density[i] - cpu.density[i]),
                          std::abs(temperature[i] - cpu.temperature[i]),
                          std::abs(fuel[i] - cpu.fuel[i])});
    EXPECT_LE(worst, 1e-5);
    EXPECT_NEAR(total(cpu.fuel), fuelBefore, 1e-9 * fuelBefore) << "the fuel is conserved";
    EXPECT_EQ(maxCovered(grid, solids, std::vector<double>(fuel.begin(), fuel.end()), 20 * dt),
              0.0);
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, SmokeDisplacementKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
