/// @file ParticleAdvectionTest.cpp
/// The particles' rules on the CPU reference (engine/simulation/ParticleMotion.h): tracers in a
/// solid-body rotation come back to their start to second order, inertial ones fall at their
/// terminal speed exactly, emission follows count and rate, solids push particles out and walls
/// keep them in; the PLY frame they are written to reads back.

#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/output/ParticleFrame.h"
#include "engine/reference/ParticleAdvection.h"
#include "engine/simulation/SolidExit.h"
#include "tests/support/TestFolder.h"

namespace modeflow {
namespace {

MacGrid unitGrid(int dim, int n) {
    MacGrid grid;
    grid.dim = dim;
    for (int a = 0; a < dim; ++a) {
        grid.cells[a] = n;
        grid.spacing[a] = 1.0 / n;
    }
    return grid;
}

/// The face field of u = ω ẑ × (x − c): exact under MAC sampling away from the walls (linear).
std::vector<double> rotation(const MacGrid& grid, double omega) {
    std::vector<double> faces(std::size_t(grid.faceTotal()), 0.0);
    for (int axis = 0; axis < 2; ++axis) {
        const auto e = grid.faceExtent(axis);
        for (int y = 0; y < e[1]; ++y)
            for (int x = 0; x < e[0]; ++x) {
                const double px = (x + (axis == 0 ? 0.0 : 0.5)) * grid.spacing[0] - 0.5;
                const double py = (y + (axis == 1 ? 0.0 : 0.5)) * grid.spacing[1] - 0.5;
                faces[std::size_t(grid.faceIndex(axis, x, y, 0))] =
                    axis == 0 ? -omega * py : omega * px;
            }
    }
    return faces;
}

ParticleSetSpec ballSet(const Vec3& centre, double radius, std::int64_t count) {
    ParticleSetSpec set;
    set.region.kind = ShapeKind::Ball;
    set.region.center = centre;
    set.region.radius = radius;
    set.count = count;
    return set;
}

/// The largest distance of a particle from where it was after `steps` steps of a turn.
double returnError(int steps) {
    const MacGrid grid = unitGrid(2, 32);
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    const double omega = 2.0 * std::numbers::pi, dt = 1.0 / steps;
    reference::ParticleAdvection particles(grid, grid, fluid, {ballSet({0.5, 0.5, 0.0}, 0.3, 50)},
                                           10.0);
    const std::vector<double> faces = rotation(grid, omega);
    // The first step seeds them at rest: take their places after it as the start.
    particles.step(faces, {}, 0.0, dt);
    const std::vector<double> start = particles.particles().position;
    for (int s = 0; s < steps; ++s) particles.step(faces, {}, (s + 1) * dt, dt);
    double worst = 0.0;
    for (std::size_t i = 0; i < start.size(); ++i)
        worst = std::max(worst, std::abs(particles.particles().position[i] - start[i]));
    return worst;
}

TEST(ParticleAdvection, TracersInASolidBodyRotationReturnToTheirStartToSecondOrder) {
    const double coarse = returnError(40), fine = returnError(80), finer = returnError(160);
    std::cout << "one turn: return error " << coarse << ", " << fine << ", " << finer
              << " at 40, 80, 160 steps\n";
    EXPECT_LT(coarse, 0.02);
    EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.15);
    EXPECT_NEAR(std::log2(fine / finer), 2.0, 0.15);
}

TEST(ParticleAdvection, InertialParticlesFallAtTheirTerminalSpeedInStillAir) {
    const MacGrid grid = unitGrid(3, 8);
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    ParticleSetSpec leaves = ballSet({0.5, 0.5, 0.9}, 0.05, 20);
    leaves.drag = 25.0;
    leaves.gravity = 9.81;
    reference::ParticleAdvection particles(grid, grid, fluid, {leaves}, 10.0);
    const std::vector<double> still(std::size_t(grid.faceTotal()), 0.0);
    const double dt = 0.01;
    particles.step(still, {}, 0.0, dt);
    const std::vector<double> seeded = particles.particles().position;
    // From rest: z(t) = z0 − w t + w (1 − e^{−dt}) / d with w = g / d, exactly at any step.
    const double w = leaves.gravity / leaves.drag;
    for (int s = 1; s < 30; ++s) particles.step(still, {}, s * dt, dt);
    const Particles& p = particles.particles();
    const double t = 30 * dt;
    const double fallen = w * t - w * (1.0 - std::exp(-leaves.drag * t)) / leaves.drag;
    for (std::size_t i = 0; i < p.size(); ++i) {
        // The first step started at rest from the seed: z0 is the seed's.
        const double z0 =
            seeded[3 * i + 2] + w * dt - w * (1.0 - std::exp(-leaves.drag * dt)) / leaves.drag;
        EXPECT_NEAR(p.position[3 * i + 2], z0 - fallen, 1e-12);
        EXPECT_NEAR(p.velocity[3 * i + 2], -w * (1.0 - std::exp(-leaves.drag * t)), 1e-12);
        EXPECT_EQ(p.position[3 * i], seeded[3 * i]);
    }
    for (int s = 30; s < 100; ++s) particles.step(still, {}, s * dt, dt);
    EXPECT_NEAR(particles.particles().velocity[2], -w, 1e-9) << "terminal speed g / drag";
}

TEST(ParticleAdvection, SetsEmitTheirCountAtStartOrAtTheirRateIntoTheFluid) {
    const MacGrid grid = unitGrid(2, 16);
    // The left half is solid wall: seeds land in the right half only.
    std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 8; ++x) fluid[std::size_t(grid.cellIndex(x, y, 0))] = 0;
    ParticleSetSpec burst = ballSet({0.5, 0.5, 0.0}, 0.3, 100);
    burst.start = 0.1;
    ParticleSetSpec stream;
    stream.region.kind = ShapeKind::Box;
    stream.region.min = {0.6, 0.1, 0.0};
    stream.region.max = {0.9, 0.2, 0.0};
    stream.rate = 250.0;
    stream.start = 0.0;
    stream.end = 0.2;
    ParticleEmission emission({burst, stream}, 1.0);
    EXPECT_EQ(emission.capacity(), 150);
    Particles particles;
    EXPECT_EQ(emission.emit(0.05, grid, fluid, particles), 12u) << "floor(250 × 0.05)";
    EXPECT_EQ(emission.emit(0.1, grid, fluid, particles), 113u) << "the burst and 13 more";
    EXPECT_EQ(emission.emit(0.5, grid, fluid, particles), 25u) << "until end = 0.2";
    EXPECT_EQ(emission.emit(0.9, grid, fluid, particles), 0u);
    ASSERT_EQ(particles.size(), 150u);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3 p{particles.position[3 * i], particles.position[3 * i + 1], 0.0};
        EXPECT_TRUE(inFluidCell(grid, fluid, p)) << i;
        EXPECT_GE(p[0], 0.5);
        if (particles.set[i] == 0) {
            EXPECT_LE(std::hypot(p[0] - 0.5, p[1] - 0.5), 0.3);
        } else {
            EXPECT_TRUE(p[1] >= 0.1 && p[1] <= 0.2);
        }
        EXPECT_EQ(particles.velocity[3 * i], 0.0) << "they start at rest";
    }
    // The same draws again from a fresh emission: seeds depend on the set and number alone.
    ParticleEmission again({burst, stream}, 1.0);
    Particles same;
    again.emit(1.0, grid, fluid, same);
    EXPECT_EQ(same.size(), particles.size());
    // A resumed emission continues where the saved particles stop.
    ParticleEmission resumed({burst, stream}, 1.0);
    Particles part;
    ParticleEmission({burst, stream}, 1.0).emit(0.05, grid, fluid, part);
    resumed.restore(part);
    EXPECT_EQ(resumed.emit(0.1, grid, fluid, part), 113u);

    // A set wholly in the wall is refused, naming it; so are too many particles.
    ParticleEmission walled({ballSet({0.2, 0.5, 0.0}, 0.1, 3)}, 1.0);
    Particles none;
    try {
        walled.emit(0.0, grid, fluid, none);
        ADD_FAILURE() << "a set in the wall was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("[[particles]] #1: 1000 draws in its ball found no "
                                             "fluid cell"),
                  std::string::npos)
            << e.what();
    }
    ParticleSetSpec flood = stream;
    flood.rate = 1e9;
    flood.end = 1e9;
    EXPECT_THROW(ParticleEmission({flood}, 1.0), Error);
    Particles foreign = part;
    foreign.set[0] = 7;
    EXPECT_THROW(resumed.restore(foreign), Error);
    foreign = part;
    foreign.position[1] = std::nan("");
    EXPECT_THROW(resumed.restore(foreign), Error);
}

TEST(ParticleAdvection, SolidsPushParticlesOutAndInertialOnesStopMovingIntoThem) {
    const MacGrid grid = unitGrid(3, 16);
    ObstacleSpec ball;
    ball.radius = 0.2;
    ball.path = {{0.0, {0.5, 0.5, 0.5}}};
    ObstacleSpec box;
    box.shape = ObstacleShape::Box;
    box.halfSize = {0.1, 0.2, 0.3};
    box.path = {{0.0, {0.5, 0.5, 0.5}}};
    box.rotation = {{0.0, {0.0, 0.0, 1.0}, 30.0}};
    ObstacleSpec capsule;
    capsule.shape = ObstacleShape::Capsule;
    capsule.radius = 0.1;
    capsule.axis = {0.2, 0.0, 0.0};
    capsule.path = {{0.0, {0.5, 0.5, 0.5}}};
    for (const ObstacleSpec& spec : {ball, box, capsule}) {
        const MovingObstacle solid{spec};
        const ObstaclePose pose = solid.poseAt(0.0);
        for (const Vec3& p :
             {Vec3{0.55, 0.52, 0.49}, Vec3{0.5, 0.5, 0.5}, Vec3{0.62, 0.45, 0.45}}) {
            const auto exit = solidExit(solid, p, pose, grid, 1e-4);
            ASSERT_TRUE(exit.has_value());
            EXPECT_FALSE(solid.covers(exit->point, pose, grid));
            // Just past the surface: 2e-4 inwards along the normal it is covered again.
            Vec3 back = exit->point;
            for (int a = 0; a < 3; ++a) back[a] -= 2e-4 * exit->normal[a];
            EXPECT_TRUE(solid.covers(back, pose, grid));
        }
        EXPECT_FALSE(solidExit(solid, {0.05, 0.05, 0.05}, pose, grid, 1e-4).has_value());
    }
    // A ball exit is radial: from (0.55, 0.5, 0.5) to (0.7 + margin, 0.5, 0.5).
    const auto radial = solidExit(MovingObstacle{ball}, {0.55, 0.5, 0.5},
                                  MovingObstacle{ball}.poseAt(0.0), grid, 1e-4);
    EXPECT_NEAR(radial->point[0], 0.7001, 1e-12);
    EXPECT_NEAR(radial->normal[0], 1.0, 1e-12);

    // Leaves falling on a still ball land on it: none inside, those on it slower than in the air.
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    ParticleSetSpec leaves = ballSet({0.5, 0.5, 0.85}, 0.08, 40);
    leaves.drag = 2.0;
    reference::ParticleAdvection particles(grid, grid, fluid, {leaves}, 10.0);
    const std::vector<double> still(std::size_t(grid.faceTotal()), 0.0);
    const std::vector<MovingObstacle> solids{MovingObstacle{ball}};
    for (int s = 0; s < 20; ++s) particles.step(still, solids, s * 0.01, 0.01);
    const Particles& p = particles.particles();
    int resting = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 x{p.position[3 * i], p.position[3 * i + 1], p.position[3 * i + 2]};
        EXPECT_FALSE(solids[0].covers(x, solids[0].poseAt(0.2), grid)) << i;
        const double r = std::hypot(x[0] - 0.5, x[1] - 0.5, x[2] - 0.5);
        if (r < 0.21 && x[2] > 0.6) {
            ++resting;
            EXPECT_LT(std::hypot(p.velocity[3 * i], p.velocity[3 * i + 1], p.velocity[3 * i + 2]),
                      leaves.gravity / leaves.drag)
                << i;
        }
    }
    EXPECT_GT(resting, 0) << "some land on the ball";
}

TEST(ParticleAdvection, WallsKeepParticlesInTheBoxAndTheFluid) {
    const MacGrid grid = unitGrid(2, 16);
    // A wall across the middle (rows 7 and 8); particles start below it, the air blows up and
    // right: they slide along the wall and stay below, and inside the box on the right.
    std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    for (int x = 0; x < 16; ++x)
        for (int y = 7; y <= 8; ++y) fluid[std::size_t(grid.cellIndex(x, y, 0))] = 0;
    std::vector<double> wind(std::size_t(grid.faceTotal()), 0.0);
    for (std::int64_t f = 0; f < grid.faceCount(0); ++f) wind[std::size_t(f)] = 1.0;
    for (std::int64_t f = grid.faceOffset(1); f < grid.faceTotal(); ++f) wind[std::size_t(f)] = 1.0;
    reference::ParticleAdvection particles(grid, grid, fluid, {ballSet({0.5, 0.2, 0.0}, 0.1, 30)},
                                           10.0);
    for (int s = 0; s < 100; ++s) particles.step(wind, {}, s * 0.02, 0.02);
    const Particles& p = particles.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_LT(p.position[3 * i + 1], 7.0 / 16.0) << i;
        EXPECT_LE(p.position[3 * i], 1.0) << i;
        EXPECT_GT(p.position[3 * i], 0.9) << i << " slid right along the wall";
        EXPECT_TRUE(inFluidCell(grid, fluid, {p.position[3 * i], p.position[3 * i + 1], 0.0}));
    }
}

TEST(ParticleAdvection, APeriodicAxisWrapsThem) {
    MacGrid grid = unitGrid(2, 16);
    grid.periodic[0] = true;
    const std::vector<std::uint8_t> fluid(std::size_t(grid.cellCount()), 1);
    // A uniform wind along the periodic x: one unit a unit of time.
    std::vector<double> wind(std::size_t(grid.faceTotal()), 0.0);
    for (std::int64_t f = 0; f < grid.faceCount(0); ++f) wind[std::size_t(f)] = 1.0;
    reference::ParticleAdvection particles(grid, grid, fluid, {ballSet({0.5, 0.5, 0.0}, 0.2, 20)},
                                           10.0);
    particles.step(wind, {}, 0.0, 0.05);
    const std::vector<double> start = particles.particles().position;
    for (int s = 1; s <= 30; ++s) particles.step(wind, {}, s * 0.05, 0.05);
    const Particles& p = particles.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        // 1.5 box lengths on: half a box from where they were, inside [0, 1).
        const double expected = start[3 * i] + 0.5 - (start[3 * i] + 0.5 >= 1.0 ? 1.0 : 0.0);
        EXPECT_NEAR(p.position[3 * i], expected, 1e-12) << i;
        EXPECT_GE(p.position[3 * i], 0.0);
        EXPECT_LT(p.position[3 * i], 1.0);
        EXPECT_EQ(p.position[3 * i + 1], start[3 * i + 1]);
    }
}

TEST(ParticleFrame, APlyPointCloudReadsBack) {
    const testing::TestFolder folder;
    const std::vector<double> position{0.1, 0.2, 0.3, -1.0, 2.5, 0.0};
    const std::vector<double> velocity{1.0, -2.0, 0.5, 0.0, 0.0, 3.0};
    const std::string name = particleFrameFileName("leaves", 7);
    EXPECT_EQ(name, "leaves_particles_0007.ply");
    writeParticleFrame(folder / name, {position, velocity, 7, 0.35, "abc"});
    std::ifstream in(folder / name, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string end = "end_header\n";
    const std::size_t body = bytes.find(end) + end.size();
    const std::string header = bytes.substr(0, body);
    for (const char* line :
         {"format binary_little_endian 1.0\n", "element vertex 2\n", "property float x\n",
          "property float vz\n", "property int id\n", "comment frame 7\n"})
        EXPECT_NE(header.find(line), std::string::npos) << line;
    ASSERT_EQ(bytes.size() - body, 2u * 28u);
    float values[6];
    std::int32_t id;
    std::memcpy(values, bytes.data() + body + 28, sizeof values);
    std::memcpy(&id, bytes.data() + body + 28 + sizeof values, sizeof id);
    EXPECT_EQ(values[1], 2.5f);
    EXPECT_EQ(values[5], 3.0f);
    EXPECT_EQ(id, 1);
    const std::vector<double> diverged{0.0, std::nan(""), 0.0};
    EXPECT_THROW(writeParticleFrame(folder / "bad.ply", {diverged, diverged, 1, 0.0, ""}), Error);
    EXPECT_FALSE(std::filesystem::exists(folder / "bad.ply"));
}

TEST(ParticleFrame, AParticleThatLeftIsLeftOutAndTheOthersKeepTheirIds) {
    const testing::TestFolder folder;
    const double gone = kParticleLeft;
    const std::vector<double> position{gone, gone, gone, -1.0, 2.5, 0.0};
    const std::vector<double> velocity{0.0, 0.0, 0.0, 0.0, 0.0, 3.0};
    writeParticleFrame(folder / "open.ply", {position, velocity, 1, 0.0, ""});
    std::ifstream in(folder / "open.ply", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string end = "end_header\n";
    const std::size_t body = bytes.find(end) + end.size();
    EXPECT_NE(bytes.substr(0, body).find("element vertex 1\n"), std::string::npos);
    ASSERT_EQ(bytes.size() - body, 28u);
    std::int32_t id;
    std::memcpy(&id, bytes.data() + body + 24, sizeof id);
    EXPECT_EQ(id, 1);
}

}  // namespace
}  // namespace modeflow
