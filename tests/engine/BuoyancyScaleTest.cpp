/// @file BuoyancyScaleTest.cpp
/// The scale of the buoyancy chain (force field → projection → modal step → reconstruction) on
/// both backends, against the grid's own pressure projection: with every divergence-free mode of
/// a small box kept, one explicit step from rest under a temperature field must move the fluid by
/// exactly dt·P(g), P the L²-orthogonal projection of the force density g onto discretely
/// divergence-free MAC fields, computed here by a pressure solve that shares no code with the
/// bases. A flux taken for a velocity, or a spacing or face area on the wrong axis (the cells are
/// not cubes), shows as a ratio away from 1; with fewer modes the same step is P_N(g), smaller
/// where g is narrower than the modes (tools/validate/README.md, "The slow plume").

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/device/Simulation.h"
#include "engine/reference/Simulation.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/TestScenes.h"
#include "tests/support/VulkanTestContext.h"
#include "tools/validate/PressureProjection.h"

namespace modeflow {
namespace {

constexpr double buoyancy = 1.7;
constexpr double dt = 0.05;

/// A box of non-cubic cells with every divergence-free mode of its grid (faces − cells + 1), in
/// closed form (no [[domain]]: the whole grid box) or `eigensolved` (a [[domain]] box reaching
/// past the grid: the same operators, through the eigensolver).
SceneSpec completeBoxScene(int dim, bool eigensolved) {
    SceneSpec scene = dim == 2
                          ? testing::gridScene({16, 12, 1}, {0.0, 0.0, 0.0}, {1.0, 0.6, 0.0}, 2)
                          : testing::gridScene({6, 5, 4}, {0.0, 0.0, 0.0}, {0.9, 0.5, 0.8}, 3);
    const MacGrid grid = MacGrid::fromSpec(scene.grid);
    std::int64_t interiorFaces = 0;
    for (int a = 0; a < dim; ++a)
        interiorFaces += grid.cellCount() / grid.cells[a] * (grid.cells[a] - 1);
    scene.name = "complete";
    if (eigensolved) scene.domain = {testing::box({-1.0, -1.0, -1.0}, {2.0, 2.0, 2.0})};
    scene.basis.velocityModes = {{1, int(interiorFaces - grid.cellCount() + 1)}};
    scene.basis.scalarModes = 0;
    scene.simulation.integrator = Integrator::Explicit;
    scene.simulation.dt = dt;
    scene.smoke.buoyancy = buoyancy;
    scene.smoke.advection = AdvectionScheme::SemiLagrangian;
    return scene;
}

/// The four complete boxes: 2D and 3D, closed form and eigensolved.
const std::vector<const RunInputs*>& completeBoxes() {
    static const RunInputs runs[] = {testing::sharedRun(completeBoxScene(2, false)),
                                     testing::sharedRun(completeBoxScene(3, false)),
                                     testing::sharedRun(completeBoxScene(2, true)),
                                     testing::sharedRun(completeBoxScene(3, true))};
    static const std::vector<const RunInputs*> all = {&runs[0], &runs[1], &runs[2], &runs[3]};
    return all;
}

std::string describe(const RunInputs& run) {
    return std::to_string(run.cache.grid.dim) + "D, " + std::to_string(run.modeCount()) +
           " modes, " + (run.cache.velocity.modes.cols() > 0 ? "eigensolved" : "closed form");
}

/// A warm blob off-centre plus a gentle tilt: a temperature with a large div-free part.
std::vector<double> warmBlob(const MacGrid& grid) {
    std::vector<double> t(std::size_t(grid.cellCount()));
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const Vec3 c{grid.cellCentre(0, x), grid.cellCentre(1, y),
                             grid.dim == 3 ? grid.cellCentre(2, z) : 0.0};
                const Vec3 centre{0.3, 0.2, 0.25};
                double r2 = 0.0;
                for (int a = 0; a < grid.dim; ++a) r2 += (c[a] - centre[a]) * (c[a] - centre[a]);
                t[std::size_t(grid.cellIndex(x, y, z))] = std::exp(-r2 / 0.02) + 0.3 * c[0];
            }
    return t;
}

/// g on every face of the grid: buoyancy × the mean temperature of the two cells an interior
/// up-facing face separates; 0 on other faces and on the box.
std::vector<double> buoyancyDensity(const MacGrid& grid, const std::vector<double>& t) {
    const int up = grid.dim - 1;
    std::vector<double> g(std::size_t(grid.faceTotal()), 0.0);
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const std::array<int, 3> p{x, y, z};
                if (p[up] == 0) continue;
                std::array<int, 3> below = p;
                --below[up];
                const double mean =
                    0.5 * (t[std::size_t(grid.cellIndex(x, y, z))] +
                           t[std::size_t(grid.cellIndex(below[0], below[1], below[2]))]);
                g[std::size_t(grid.faceIndex(up, x, y, z))] = buoyancy * mean;
            }
    return g;
}

struct Comparison {
    double ratio = 0.0;  ///< ⟨u, P g⟩ / ⟨P g, P g⟩ / dt: 1 when the scale is right
    double error = 0.0;  ///< max |u − dt P g| / max |dt P g|
};

Comparison compare(const std::vector<double>& u, const std::vector<double>& projected) {
    double dot = 0.0, norm = 0.0, maxError = 0.0, maxValue = 0.0;
    for (std::size_t f = 0; f < u.size(); ++f) {
        dot += u[f] * projected[f];
        norm += projected[f] * projected[f];
        maxError = std::max(maxError, std::abs(u[f] - dt * projected[f]));
        maxValue = std::max(maxValue, std::abs(dt * projected[f]));
    }
    return {dot / norm / dt, maxError / maxValue};
}

/// One step of `simulation` from rest in the warm blob, against dt·P(g).
Comparison stepFromRest(Simulator& simulation, const MacGrid& grid) {
    const std::vector<double> t = warmBlob(grid);
    simulation.restore(0.0, Eigen::VectorXd::Zero(simulation.velocity().size()), SmokeFields{t, t});
    simulation.advanceSteps(1);
    return compare(simulation.faceVelocity(),
                   validate::pressureProjection(grid, buoyancyDensity(grid, t)));
}

TEST(BuoyancyScale, ProjectionIsNotTrivial) {
    // The blob's force is far from a gradient: most of it survives the projection.
    for (const RunInputs* run : completeBoxes()) {
        const int dim = run->cache.grid.dim;
        const MacGrid grid = MacGrid::fromSpec(run->cache.grid);
        const std::vector<double> g = buoyancyDensity(grid, warmBlob(grid));
        const std::vector<double> pg = validate::pressureProjection(grid, g);
        double gNorm = 0.0, pNorm = 0.0;
        for (std::size_t f = 0; f < g.size(); ++f) gNorm += g[f] * g[f], pNorm += pg[f] * pg[f];
        EXPECT_GT(std::sqrt(pNorm / gNorm), 0.2) << dim << "D";
        EXPECT_LT(std::sqrt(pNorm / gNorm), 0.99) << dim << "D";
    }
}

TEST(BuoyancyScale, CompleteBasisStepIsThePressureProjectionOnTheCpuReference) {
    for (const RunInputs* run : completeBoxes()) {
        reference::Simulation simulation(run->cache, *run->coefficients, run->settings,
                                         run->smokeMask);
        const Comparison c = stepFromRest(simulation, MacGrid::fromSpec(run->cache.grid));
        std::cout << describe(*run) << ": u / (dt P g) = " << c.ratio << ", max error " << c.error
                  << "\n";
        EXPECT_NEAR(c.ratio, 1.0, 1e-9) << describe(*run);
        EXPECT_LE(c.error, 1e-9) << describe(*run);
    }
}

class BuoyancyScaleDevice : public testing::VulkanTest {};

TEST_P(BuoyancyScaleDevice, CompleteBasisStepIsThePressureProjectionOnTheDevice) {
    for (const RunInputs* run : completeBoxes()) {
        {
            device::Simulation simulation(context(), run->cache, *run->coefficients, run->settings,
                                          run->smokeMask);
            const Comparison c = stepFromRest(simulation, MacGrid::fromSpec(run->cache.grid));
            std::cout << describe(*run) << ", device: u / (dt P g) = " << c.ratio << ", max error "
                      << c.error << "\n";
            EXPECT_NEAR(c.ratio, 1.0, 1e-5) << describe(*run);
            EXPECT_LE(c.error, 1e-5) << describe(*run);
        }
        expectNoValidationMessages();
    }
}

INSTANTIATE_TEST_SUITE_P(Validation, BuoyancyScaleDevice, ::testing::Values(false, true),
                         testing::validationName);

}  // namespace
}  // namespace modeflow
