/// @file ObstacleKernelTest.cpp
/// The moving-obstacle correction on the device (ObstacleCorrection: obstacle_mismatch.comp,
/// projection, modal_correct.comp) against its CPU reference obstacleCorrection, in a disk and
/// across the seam of a periodic channel, for every shape (a mesh's level set included), still in
/// its frame or turning.

#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/core/RuntimeLimits.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/ObstacleCorrection.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/reference/ObstacleCorrection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/vulkan/CommandSequence.h"
#include "tests/support/RealBases.h"
#include "tests/support/TestSolids.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

class ObstacleKernelTest : public testing::VulkanTest {};

/// v after the device's correction: reconstruction, mismatch, projection, v −= Δv.
Eigen::VectorXd deviceCorrected(const vulkan::VulkanContext& context, const BasisCache& cache,
                                const Eigen::VectorXd& v,
                                const std::vector<MovingObstacle>& obstacles, double t) {
    const int n = int(v.size());
    const device::ModeBuffer modes(context, cache.velocity.modes);
    const device::ReconstructionKernel reconstruction(context, cache);
    device::ObstacleCorrection correction(context, cache);
    std::vector<float> state(device::paddedSize(n), 0.0f);
    for (int k = 0; k < n; ++k) state[std::size_t(k)] = float(v[k]);
    vulkan::DeviceBuffer vBuffer = vulkan::DeviceBuffer::fromValues<float>(context, state, "v");
    const vulkan::DeviceBuffer faces = reconstruction.makeFaceField();
    correction.setObstacles(obstacles, t);
    vulkan::CommandSequence sequence(context);
    reconstruction.record(sequence, modes, vBuffer, faces);
    correction.record(sequence, modes, faces, vBuffer);
    sequence.submitAndWait();
    vBuffer.download<float>(state);
    Eigen::VectorXd got(n);
    for (int k = 0; k < n; ++k) got[k] = state[std::size_t(k)];
    return got;
}

TEST_P(ObstacleKernelTest, CorrectionEqualsTheCpuReference) {
    // In the disk, and on the seam of the periodic channel over [0, 2] × [0, 1] (the centre at
    // x = 2.05 at t = 0.5: it covers faces at both ends).
    for (const bool periodic : {false, true}) {
        const BasisCache& cache = periodic ? testing::periodicChannel2d() : testing::disk2d();
        RandomVelocitySpec random;
        const Eigen::VectorXd v =
            randomVelocity(int(cache.velocity.modes.cols()), random).cast<float>().cast<double>();
        for (const ObstacleShape shape :
             {ObstacleShape::Ball, ObstacleShape::Box, ObstacleShape::Capsule, ObstacleShape::Mesh})
            for (const bool turning : {false, true}) {
                ObstacleSpec spec;
                spec.shape = shape;
                spec.radius = 0.2;
                spec.halfSize = {0.25, 0.15, 0.0};
                spec.axis = {0.1, 0.2, 0.0};
                spec.scale = 1.5;
                spec.path = {{0.0, {-0.3, 0.1, 0.0}}, {1.0, {0.4, -0.2, 0.0}}};
                if (periodic) spec.path = {{0.0, {1.7, 0.6, 0.0}}, {1.0, {2.4, 0.4, 0.0}}};
                // Turning: the shape's frame at 100° at t = 0.5, spinning at 180°/s.
                if (turning)
                    spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 10.0}, {1.0, {0.0, 0.0, 1.0}, 190.0}};
                std::vector<MovingObstacle> obstacles{MovingObstacle{spec}};
                if (shape == ObstacleShape::Mesh) obstacles[0].levelSet = testing::lShapedLattice();
                const Eigen::VectorXd expected =
                    v - reference::obstacleCorrection(
                            cache, reference::reconstructFaceField(cache, v), obstacles, 0.5);
                const Eigen::VectorXd got = deviceCorrected(context(), cache, v, obstacles, 0.5);
                const double error =
                    (got - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
                std::cout << (periodic ? "periodic channel" : "disk") << ", shape " << int(shape)
                          << ": relative error " << error << ", |correction| "
                          << (expected - v).norm() << "\n";
                EXPECT_LE(error, 1e-5);
                expectNoValidationMessages();
            }
    }
}

TEST_P(ObstacleKernelTest, ADeformingMeshsOwnVelocityEqualsTheCpuReference) {
    // Two files of the L-shaped lattice, each with a velocity of its own material (a shear and a
    // swirl), the second shown at t = 0.5 (two files per unit time), moving and turning: the
    // mismatch takes the material's deformation on both backends.
    const BasisCache& cache = testing::disk2d();
    RandomVelocitySpec random;
    const Eigen::VectorXd v =
        randomVelocity(int(cache.velocity.modes.cols()), random).cast<float>().cast<double>();
    const auto file = [](double shear, double swirl) {
        auto set = std::make_shared<SolidLevelSet>(*testing::lShapedLattice());
        set->velocity.resize(3 * set->depth.size());
        for (int z = 0; z < set->samples[2]; ++z)
            for (int y = 0; y < set->samples[1]; ++y)
                for (int x = 0; x < set->samples[0]; ++x) {
                    const double px = set->origin[0] + x * set->spacing,
                                 py = set->origin[1] + y * set->spacing;
                    const std::size_t s =
                        3 *
                        (std::size_t(x) + std::size_t(set->samples[0]) *
                                              (std::size_t(y) + std::size_t(set->samples[1]) * z));
                    set->velocity[s] = float(shear * py - swirl * py);
                    set->velocity[s + 1] = float(swirl * px);
                    set->velocity[s + 2] = 0.0f;
                    set->maxSpeed =
                        std::max(set->maxSpeed, std::hypot(shear * py - swirl * py, swirl * px));
                }
        return std::shared_ptr<const SolidLevelSet>(set);
    };
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Mesh;
    spec.scale = 1.5;
    spec.sequenceRate = 2.0;
    spec.path = {{0.0, {-0.3, 0.1, 0.0}}, {1.0, {0.4, -0.2, 0.0}}};
    spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 10.0}, {1.0, {0.0, 0.0, 1.0}, 190.0}};
    MovingObstacle obstacle{spec};
    obstacle.sequence = {file(2.0, 0.0), file(0.5, 3.0)};
    obstacle.levelSet = obstacle.sequence.front();
    ASSERT_EQ(obstacle.poseAt(0.5).shape, obstacle.sequence[1].get());
    const std::vector<MovingObstacle> obstacles{obstacle};
    const Eigen::VectorXd expected =
        v - reference::obstacleCorrection(cache, reference::reconstructFaceField(cache, v),
                                          obstacles, 0.5);
    // Its own velocity counts: the correction differs from the rigid one's.
    MovingObstacle rigid = obstacle;
    rigid.sequence = {testing::lShapedLattice(), testing::lShapedLattice()};
    const Eigen::VectorXd rigidExpected =
        v - reference::obstacleCorrection(cache, reference::reconstructFaceField(cache, v),
                                          std::vector<MovingObstacle>{rigid}, 0.5);
    EXPECT_GT((expected - rigidExpected).norm(), 1e-3 * expected.norm());
    const Eigen::VectorXd got = deviceCorrected(context(), cache, v, obstacles, 0.5);
    const double error =
        (got - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
    std::cout << "deforming mesh: relative error " << error << "\n";
    EXPECT_LE(error, 1e-5);
    expectNoValidationMessages();
}

TEST_P(ObstacleKernelTest, AsManyObstaclesAsTheSceneTakesEqualTheCpuReference) {
    // As many small balls and boxes as the correction holds (obstacles and driving sources), on
    // a lattice in the disk, a quarter of them turning.
    const BasisCache& cache = testing::disk2d();
    RandomVelocitySpec random;
    const Eigen::VectorXd v =
        randomVelocity(int(cache.velocity.modes.cols()), random).cast<float>().cast<double>();
    std::vector<MovingObstacle> obstacles;
    for (int o = 0; o < maxVelocityRegions; ++o) {
        ObstacleSpec spec;
        spec.shape = o % 2 ? ObstacleShape::Box : ObstacleShape::Ball;
        spec.radius = 0.05;
        spec.halfSize = {0.05, 0.03, 0.0};
        spec.path = {{0.0, {-0.6 + 0.11 * (o % 12), -0.6 + 0.11 * (o / 12), 0.0}}};
        if (o % 4 == 1) spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {1.0, {0.0, 0.0, 1.0}, 90.0}};
        obstacles.push_back({spec});
    }
    const std::vector<double> faces = reference::reconstructFaceField(cache, v);
    int covered = 0;
    for (const double m : reference::obstacleMismatch(cache, faces, obstacles, 0.5))
        covered += m != 0.0;
    const Eigen::VectorXd expected =
        v - reference::obstacleCorrection(cache, faces, obstacles, 0.5);
    const Eigen::VectorXd got = deviceCorrected(context(), cache, v, obstacles, 0.5);
    const double error =
        (got - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
    std::cout << maxVelocityRegions << " obstacles, " << covered
              << " covered faces: relative error " << error << "\n";
    EXPECT_GT(covered, maxVelocityRegions) << "the obstacles cover faces";
    EXPECT_LE(error, 1e-5);
    expectNoValidationMessages();
}

TEST_P(ObstacleKernelTest, WhereObstaclesOverlapTheFirstOneDecides) {
    // Two balls and a turning box overlapping, each moving its own way, in the disk and in the
    // 3D ball: on the faces two cover, the first one's material velocity sets the mismatch.
    for (const BasisCache* cache : {&testing::disk2d(), &testing::ball3d()}) {
        RandomVelocitySpec random;
        const Eigen::VectorXd v =
            randomVelocity(int(cache->velocity.modes.cols()), random).cast<float>().cast<double>();
        ObstacleSpec right, down, turning;
        right.radius = 0.3;
        right.path = {{0.0, {-0.2, 0.0, 0.0}}, {1.0, {0.8, 0.0, 0.0}}};
        down.radius = 0.35;
        down.path = {{0.0, {0.1, 0.5, 0.05}}, {1.0, {0.1, -1.5, 0.05}}};
        turning.shape = ObstacleShape::Box;
        turning.halfSize = {0.4, 0.1, 0.2};
        turning.path = {{0.0, {0.05, 0.2, 0.0}}};
        turning.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {1.0, {0.0, 0.0, 1.0}, 300.0}};
        const std::vector<MovingObstacle> obstacles{{right}, {down}, {turning}};
        const std::vector<double> faces = reference::reconstructFaceField(*cache, v);
        const Eigen::VectorXd expected =
            v - reference::obstacleCorrection(*cache, faces, obstacles, 0.5);
        const Eigen::VectorXd got = deviceCorrected(context(), *cache, v, obstacles, 0.5);
        const double error =
            (got - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
        std::cout << cache->grid.dim << "D, three overlapping obstacles: relative error " << error
                  << "\n";
        EXPECT_LE(error, 1e-5) << cache->grid.dim << "D";
        expectNoValidationMessages();
    }
}

TEST_P(ObstacleKernelTest, AMeshObstacleWithoutItsLevelSetIsRefused) {
    const BasisCache& cache = testing::disk2d();
    ObstacleSpec spec;
    spec.shape = ObstacleShape::Mesh;
    spec.meshFile = "car.obj";
    spec.path = {{0.0, {0.0, 0.0, 0.0}}};
    const std::vector<MovingObstacle> obstacles{MovingObstacle{spec}};
    device::ObstacleCorrection correction(context(), cache);
    try {
        correction.setObstacles(obstacles, 0.0);
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("obstacle #1 (mesh car.obj) has no level set"),
                  std::string::npos)
            << e.what();
    }
    std::vector<MovingObstacle> tooMany(std::size_t(maxVelocityRegions + 1), obstacles[0]);
    for (MovingObstacle& o : tooMany) o.spec.shape = ObstacleShape::Ball;
    EXPECT_THROW(correction.setObstacles(tooMany, 0.0), Error);
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(PlainAndValidated, ObstacleKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
