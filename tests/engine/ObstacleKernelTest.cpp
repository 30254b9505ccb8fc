/// @file ObstacleKernelTest.cpp
/// The moving-obstacle correction on the device (ObstacleCorrection: obstacle_mismatch.comp,
/// projection, modal_correct.comp) against its CPU reference obstacleCorrection, in a disk and
/// across the seam of a periodic channel, for every shape, still in its frame or turning.

#include <gtest/gtest.h>

#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/ObstacleCorrection.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/reference/ObstacleCorrection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/vulkan/CommandSequence.h"
#include "tests/support/RealBases.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

class ObstacleKernelTest : public testing::VulkanTest {};

TEST_P(ObstacleKernelTest, CorrectionEqualsTheCpuReference) {
    // In the disk, and on the seam of the periodic channel over [0, 2] × [0, 1] (the centre at
    // x = 2.05 at t = 0.5: it covers faces at both ends).
    for (const bool periodic : {false, true}) {
        const BasisCache& cache = periodic ? testing::periodicChannel2d() : testing::disk2d();
        const int n = int(cache.velocity.modes.cols());
        RandomVelocitySpec random;
        const Eigen::VectorXd v = randomVelocity(n, random).cast<float>().cast<double>();
        for (const ObstacleShape shape :
             {ObstacleShape::Ball, ObstacleShape::Box, ObstacleShape::Capsule})
            for (const bool turning : {false, true}) {
                ObstacleSpec spec;
                spec.shape = shape;
                spec.radius = 0.2;
                spec.halfSize = {0.25, 0.15, 0.0};
                spec.axis = {0.1, 0.2, 0.0};
                spec.path = {{0.0, {-0.3, 0.1, 0.0}}, {1.0, {0.4, -0.2, 0.0}}};
                if (periodic) spec.path = {{0.0, {1.7, 0.6, 0.0}}, {1.0, {2.4, 0.4, 0.0}}};
                // Turning: the shape's frame at 100° at t = 0.5, spinning at 180°/s.
                if (turning)
                    spec.rotation = {{0.0, {0.0, 0.0, 1.0}, 10.0}, {1.0, {0.0, 0.0, 1.0}, 190.0}};
                const std::vector<MovingObstacle> obstacles{MovingObstacle{spec}};
                const Eigen::VectorXd expected =
                    v - reference::obstacleCorrection(
                            cache, reference::reconstructFaceField(cache, v), obstacles, 0.5);
                {
                    const device::ModeBuffer modes(context(), cache.velocity.modes);
                    const device::ReconstructionKernel reconstruction(context(), cache);
                    device::ObstacleCorrection correction(context(), cache);
                    std::vector<float> state(device::paddedSize(n), 0.0f);
                    for (int k = 0; k < n; ++k) state[std::size_t(k)] = float(v[k]);
                    vulkan::DeviceBuffer vBuffer =
                        vulkan::DeviceBuffer::fromValues<float>(context(), state, "v");
                    const vulkan::DeviceBuffer faces = reconstruction.makeFaceField();
                    correction.setObstacles(obstacles, 0.5);
                    vulkan::CommandSequence sequence(context());
                    reconstruction.record(sequence, modes, vBuffer, faces);
                    correction.record(sequence, modes, faces, vBuffer);
                    sequence.submitAndWait();
                    vBuffer.download<float>(state);
                    Eigen::VectorXd got(n);
                    for (int k = 0; k < n; ++k) got[k] = state[std::size_t(k)];
                    const double error = (got - expected).lpNorm<Eigen::Infinity>() /
                                         expected.lpNorm<Eigen::Infinity>();
                    std::cout << (periodic ? "periodic channel" : "disk") << ", shape "
                              << int(shape) << ": relative error " << error << ", |correction| "
                              << (expected - v).norm() << "\n";
                    EXPECT_LE(error, 1e-5);
                }
                expectNoValidationMessages();
            }
    }
}

INSTANTIATE_TEST_SUITE_P(PlainAndValidated, ObstacleKernelTest, ::testing::Bool(),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
