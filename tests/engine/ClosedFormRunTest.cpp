/// @file ClosedFormRunTest.cpp
/// A run on a closed-form basis (CPU reference) goes through the separable transforms and never
/// forms the columns, and is the run on the same basis stored as columns: buoyant smoke from a
/// source, a moving obstacle, a few steps, equal face velocities, states and smoke.

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/format/SeparableModes.h"
#include "engine/reference/Simulation.h"
#include "precompute/Precompute.h"
#include "tests/support/TestScenes.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {
namespace {

double relative(const std::vector<double>& a, const std::vector<double>& b) {
    double diff = 0.0, size = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        diff = std::max(diff, std::abs(a[i] - b[i]));
        size = std::max(size, std::abs(b[i]));
    }
    return diff / size;
}

TEST(ClosedFormRun, TheReferenceRunTransformsAndEqualsTheRunOnTheColumns) {
    SceneSpec scene = testing::gridScene({12, 10, 9}, {0.0, 0.0, 0.0}, {1.2, 1.0, 0.9}, 3);
    scene.basis.velocityModes = {{1, 80}};
    scene.basis.scalarModes = 0;
    scene.smoke.buoyancy = 2.0;
    scene.simulation.dt = 0.02;
    SourceSpec source;
    source.shape = testing::ball({0.6, 0.5, 0.15}, 0.12);
    source.density = source.temperature = 1.0;
    scene.sources = {source};
    ObstacleSpec paddle;
    paddle.radius = 0.15;
    paddle.path = {{0.0, {0.3, 0.5, 0.5}}, {1.0, {0.9, 0.5, 0.5}}};
    scene.obstacles = {paddle};
    Progress quiet = Progress::silent();
    BasisCache closed = computeBasis(scene, quiet);
    ASSERT_EQ(closed.velocity.source, BasisSource::ClosedForm);
    BasisCache columns = closed;
    columns.velocity.source = BasisSource::Eigensolve;
    columns.velocity.modes =
        velocityModeFluxes(closed.grid, closed.faces, closed.velocity.separable);

    const RunInputs a = prepareRun(scene, closed), b = prepareRun(scene, columns);
    EXPECT_EQ(a.cache.velocity.modes.cols(), 0) << "a closed-form run forms no columns";
    reference::Simulation transformed(a.cache, *a.coefficients, a.settings, a.smokeMask);
    reference::Simulation dense(b.cache, *b.coefficients, b.settings, b.smokeMask);
    for (int step = 0; step < 6; ++step) {
        transformed.advanceSteps(1);
        dense.advanceSteps(1);
    }
    const Eigen::VectorXd v1 = transformed.velocity(), v2 = dense.velocity();
    const double state = (v1 - v2).cwiseAbs().maxCoeff() / v2.cwiseAbs().maxCoeff(),
                 faces = relative(transformed.faceVelocity(), dense.faceVelocity()),
                 smoke = relative(transformed.smoke().density, dense.smoke().density);
    EXPECT_GT(v2.norm(), 0.0);
    EXPECT_LE(state, 1e-12);
    EXPECT_LE(faces, 1e-12);
    EXPECT_LE(smoke, 1e-12);
    std::printf(
        "[ measured ] 6 steps, transforms against columns: state %.1e, face velocity %.1e, smoke "
        "%.1e\n",
        state, faces, smoke);
}

}  // namespace
}  // namespace modeflow
