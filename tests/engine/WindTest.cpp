/// @file WindTest.cpp
/// `[wind]` on the CPU reference (engine/simulation/WindTransport.h): the modes' advection by the
/// wind against its analytic dispersion on a periodic box, the energy budget of a walled box with
/// the wind's outflow (to round-off over 1000 midpoint steps), every integrator converging to the
/// same solution, smoke that arrives clean upstream and leaves downstream, and a solid that holds
/// the wind off.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/core/MacSampling.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/reference/Simulation.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/run/Backend.h"
#include "engine/simulation/WindTransport.h"
#include "precompute/Precompute.h"
#include "tests/support/EnergyBudget.h"
#include "tests/support/SmokeTestFields.h"
#include "tests/support/TestScenes.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {
namespace {

/// A 2D box over [0, 2] × [0, 1] of 32 × 16 cells and `modes` closed-form modes.
SceneSpec windBox(int modes, std::array<bool, 3> periodic = {false, false, false}) {
    SceneSpec scene = testing::gridScene({32, 16, 1}, {0.0, 0.0, 0.0}, {2.0, 1.0, 0.0}, 2);
    scene.grid.periodic = periodic;
    scene.basis.velocityModes = {{1, modes}};
    scene.basis.scalarModes = 0;
    return scene;
}

RunInputs prepared(const SceneSpec& scene) {
    Progress quiet = Progress::silent();
    return prepareRun(scene, computeBasis(scene, quiet), RunParts::Dynamics);
}

TEST(Wind, AlongAPeriodicAxisItTurnsEachWaveAtItsDiscreteFrequency) {
    // u' = A cos(kx) + B sin(kx) ŷ in a wind U x̂: Ȧ = −ωB, Ḃ = ωA with ω = U sin(kΔx)/Δx for
    // the centred difference; a Galilean shift, so D is antisymmetric.
    const RunInputs run = prepared(windBox(40, {true, true, false}));
    const double u = 1.5, dx = 2.0 / 32;
    const WindTransport wind(run.cache, WindSpec{{u, 0.0, 0.0}});
    const Eigen::MatrixXd& d = wind.matrix();
    EXPECT_LE((d + d.transpose()).cwiseAbs().maxCoeff(), 1e-12 * d.cwiseAbs().maxCoeff());
    int waves = 0;
    const auto& modes = run.cache.velocity.separable;
    for (std::size_t p = 0; p < modes.size(); ++p) {
        if (modes[p].wave[1] != 0 || modes[p].wave[0] == 0) continue;
        for (std::size_t q = p + 1; q < modes.size(); ++q) {
            if (modes[q].wave != modes[p].wave) continue;
            const double omega = u * std::sin(2.0 * std::numbers::pi * modes[p].wave[0] / 32) / dx;
            EXPECT_NEAR(std::abs(d(int(p), int(q))), omega, 1e-9 * omega) << p << " " << q;
            EXPECT_NEAR(d(int(p), int(p)), 0.0, 1e-12 * omega);
            // The pair is turned within itself, by nothing else.
            EXPECT_NEAR(d.col(int(p)).norm(), omega, 1e-9 * omega);
            ++waves;
        }
    }
    EXPECT_GE(waves, 3);
}

TEST(Wind, TheEnergyChangesByWhatTheWindCarriesOutToRoundOff) {
    // Midpoint: E_{n+1} − E_n = h v̄ᵀ(C(v̄, v̄) + D v̄) = h v̄ᵀ D v̄ = −h·(outflow + shear power at
    // v̄): the outflow's kinetic energy flux, and in a boundary layer the shear's production.
    // And with the top open ([grid] open, eigensolved): the open side's faces weigh half a cell.
    const RunInputs closed = prepared(windBox(60));
    SceneSpec openTop = windBox(60);
    openTop.grid.open[3] = true;
    const RunInputs open = prepared(openTop);
    WindSpec layer{{0.8, 0.0, 0.0}, WindProfile::BoundaryLayer, 0.4};
    const std::pair<const RunInputs*, WindSpec> cases[] = {{&closed, WindSpec{{1.0, 0.0, 0.0}}},
                                                           {&closed, WindSpec{{-0.6, 0.35, 0.0}}},
                                                           {&closed, layer},
                                                           {&open, WindSpec{{0.7, 0.0, 0.0}}},
                                                           {&open, layer}};
    for (const auto& [run, spec] : cases) {
        const Vec3& u = spec.velocity;
        const bool uniform = spec.profile == WindProfile::Uniform;  // clang 14 cannot capture spec
        auto wind = std::make_shared<WindTransport>(run->cache, spec);
        FluidParameters parameters;
        parameters.linear = wind;
        const FluidSystem system(*run->coefficients, parameters);
        ModalIntegrator integrator(system, IntegratorSettings{Integrator::Midpoint});
        Eigen::VectorXd v = testing::unitEnergyState(system.dimension(), 7);
        const double h = 0.01, e0 = 0.5 * v.squaredNorm();
        double worstPower = 0.0, carriedOut = 0.0;
        const testing::EnergyBudget budget = testing::midpointEnergyBudget(
            integrator, *wind, v, h, 1000,
            [&](const Eigen::VectorXd& mid, const Eigen::VectorXd& dMid) {
                const double outflow = wind->outflowPower(mid), shear = wind->shearPower(mid),
                             power = outflow + shear;
                worstPower = std::max(worstPower, std::abs(mid.dot(dMid) + power) /
                                                      std::max(outflow + std::abs(shear), 1e-300));
                if (uniform) {
                    EXPECT_EQ(shear, 0.0);
                }
                carriedOut += h * power;
            });
        const double e1 = 0.5 * v.squaredNorm();
        EXPECT_LE(budget.worstStep, 1e-13);
        EXPECT_LE(budget.drift, 1e-11);
        EXPECT_LE(worstPower, 1e-10) << "vᵀDv is the outflow's kinetic energy flux and the shear's";
        EXPECT_NEAR(e0 - e1, carriedOut, 1e-10 * e0);
        EXPECT_LT(e1, 0.8 * e0) << "the wind carries the disturbance out";
        std::printf(
            "[ measured ] wind (%g, %g)%s%s, 1000 midpoint steps: energy %.4f -> %.4f, carried "
            "out and given to the shear %.4f; worst step |dE - h v.Dv| %.1e E0, drift %.1e E0\n",
            u[0], u[1], spec.profile == WindProfile::Uniform ? "" : " in a boundary layer",
            run == &open ? " under an open top" : "", e0, e1, carriedOut, budget.worstStep,
            budget.drift);
    }
}

TEST(Wind, ARunsModalStepperCarriesItOnEitherBackend) {
    // `modeflow modes` steps the dynamics alone (Backend::makeModalStepper): the wind is there as
    // in a simulation, so the energy leaves as FluidSystem with the wind's term says.
    SceneSpec scene = windBox(30);
    scene.wind = WindSpec{{1.0, 0.0, 0.0}, WindProfile::BoundaryLayer, 0.3};
    scene.initial.velocity = InitialVelocity::Random;
    const RunInputs run = prepared(scene);
    FluidParameters parameters;
    parameters.linear = std::make_shared<WindTransport>(run.cache, *scene.wind);
    const FluidSystem system(*run.coefficients, parameters);
    ModalIntegrator integrator(system, IntegratorSettings{Integrator::Midpoint});
    Eigen::VectorXd v = run.initialVelocity;
    for (int s = 0; s < 50; ++s) integrator.step(v, 0.02);
    EXPECT_LT(v.squaredNorm(), 0.9 * run.initialVelocity.squaredNorm());
    for (const BackendKind kind : kBackends) {
        const Backend backend(BackendChoice{kind, {}});
        const std::unique_ptr<ModalStepping> stepper =
            backend.makeModalStepper(run, Integrator::Midpoint);
        for (int s = 0; s < 50; ++s) stepper->step(0.02);
        EXPECT_LE((stepper->state() - v).norm(),
                  (kind == BackendKind::CpuReference ? 1e-12 : 1e-5) * v.norm())
            << capabilitiesOf(kind).name;
    }
}

TEST(Wind, EveryIntegratorAdvancesTheWindsTerm) {
    // Small steps of every scheme land on one solution (RK4 at a tenth of the step as the
    // reference): the term is in R, its Jacobian, its products and the frozen right-hand side.
    const RunInputs run = prepared(windBox(30));
    FluidParameters parameters;
    parameters.linear = std::make_shared<WindTransport>(run.cache, WindSpec{{1.2, -0.4, 0.0}});
    const FluidSystem system(*run.coefficients, parameters);
    const Eigen::VectorXd start = testing::unitEnergyState(system.dimension(), 3);
    const auto advance = [&](Integrator scheme, double h, int steps) {
        ModalIntegrator integrator(system, IntegratorSettings{scheme});
        Eigen::VectorXd v = start;
        for (int s = 0; s < steps; ++s) integrator.step(v, h);
        return v;
    };
    const Eigen::VectorXd exact = advance(Integrator::Rk4, 0.0005, 400);
    const Eigen::VectorXd still = [&] {
        const FluidSystem calm(*run.coefficients);
        ModalIntegrator integrator(calm, IntegratorSettings{Integrator::Rk4});
        Eigen::VectorXd v = start;
        for (int s = 0; s < 400; ++s) integrator.step(v, 0.0005);
        return v;
    }();
    EXPECT_GT((exact - still).norm(), 0.1 * start.norm()) << "the wind changes the flow";
    for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                                    Integrator::Trapezoidal, Integrator::Linearized}) {
        const double error = (advance(scheme, 0.005, 40) - exact).norm() / exact.norm();
        EXPECT_LE(error, scheme == Integrator::Explicit ? 0.1 : 2e-3) << int(scheme);
        std::printf("[ measured ] scheme %d: %.1e from the reference\n", int(scheme), error);
    }
}

TEST(Wind, TheSidesItCrossesCarryItAndTheOthersStayWalls) {
    const MacGrid grid = MacGrid::fromSpec(windBox(10).grid);
    const Vec3 u{0.8, 0.0, 0.0};
    std::vector<double> velocity(std::size_t(grid.faceTotal()), 0.0);
    addWind(grid, WindSpec{u}, velocity);
    const MacGrid open = withWindThrough(grid, u);
    EXPECT_TRUE(open.flowThrough[0]);
    EXPECT_FALSE(open.flowThrough[1]);
    for (const Vec3 point : {Vec3{0.1, 3.0, 0.5}, Vec3{31.9, 15.9, 0.5}, Vec3{-2.0, 8.0, 0.5}}) {
        EXPECT_DOUBLE_EQ(sampleVelocityGrid(open, std::span<const double>(velocity), point)[0],
                         0.8);
        // A sealed box's walls read as 0 whatever the field holds there.
        EXPECT_LT(sampleVelocityGrid(grid, std::span<const double>(velocity), point)[0], 0.8);
    }
    // Along a periodic axis there are no sides to open.
    MacGrid torus = grid;
    torus.periodic = {true, true, false};
    EXPECT_FALSE(withWindThrough(torus, u).flowThrough[0]);
}

TEST(Wind, ABoundaryLayerSlowsTheAirOverTheFloorAndItsShearWorksOnTheDisturbance) {
    // U (h / δ)^(1/7) below δ = 0.5 over the floor of [0, 2] × [0, 1] (32 × 16 cells), U above.
    const RunInputs run = prepared(windBox(60));
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
    const WindSpec layer{{1.0, 0.0, 0.0}, WindProfile::BoundaryLayer, 0.5};
    std::vector<double> velocity(std::size_t(grid.faceTotal()), 0.0);
    addWind(grid, layer, velocity);
    for (int y = 0; y < 16; ++y) {
        const double h = (y + 0.5) / 16.0;
        const double expected = h < 0.5 ? std::pow(h / 0.5, 1.0 / 7.0) : 1.0;
        for (const int x : {0, 17, 32})  // the inflow side, inside, the outflow side
            EXPECT_DOUBLE_EQ(velocity[std::size_t(grid.faceIndex(0, x, y, 0))], expected) << y;
    }
    for (std::int64_t f = grid.faceOffset(1); f < grid.faceTotal(); ++f)
        EXPECT_EQ(velocity[std::size_t(f)], 0.0);
    EXPECT_EQ(windSlope(layer, 0.7), 0.0);
    EXPECT_NEAR(windSlope(layer, 0.25), (1.0 / 7.0) / 0.5 * std::pow(0.5, -6.0 / 7.0), 1e-15);
    // The shear's term is there: D differs from the uniform wind's with the same factors, and
    // works on a disturbance (the energy identity with it: TheEnergyChangesByWhatTheWindCarries…).
    const WindTransport sheared(run.cache, layer);
    const Eigen::VectorXd v = testing::unitEnergyState(60, 9);
    EXPECT_GT(std::abs(sheared.shearPower(v)), 1e-3 * sheared.outflowPower(v));
    WindSpec uniform = layer;
    uniform.profile = WindProfile::Uniform;
    const WindTransport plain(run.cache, uniform);
    EXPECT_EQ(plain.shearPower(v), 0.0);
    EXPECT_GT((sheared.matrix() - plain.matrix()).norm(), 0.01 * plain.matrix().norm());
    // A boundary layer needs a floor and a wind along it.
    WindSpec upward = layer;
    upward.velocity = {1.0, 0.5, 0.0};
    EXPECT_THROW(WindTransport(run.cache, upward), Error);
}

TEST(Wind, ItsAirBringsItsSmokeAndHeatIn) {
    // A box of clean, cool air in a wind of hazy, warm air: after three crossings the box holds
    // the wind's density and temperature everywhere, and no fuel comes in with it.
    const MacGrid grid = MacGrid::fromSpec(windBox(10).grid);
    const std::vector<std::uint8_t> mask(std::size_t(grid.cellCount()), 1);
    WindSpec hazy{{-0.5, 0.7, 0.0}};
    hazy.density = 0.3;
    hazy.temperature = -0.2;
    for (const AdvectionScheme scheme :
         {AdvectionScheme::SemiLagrangian, AdvectionScheme::MacCormack}) {
        reference::SmokeAdvection windy(grid, 1, mask);
        windy.setWind(hazy);
        std::vector<double> velocity(std::size_t(grid.faceTotal()), 0.0);
        addWind(grid, hazy, velocity);
        const std::vector<double> clean(mask.size(), 0.0);
        SmokeFields fields{clean, clean, clean, clean};
        for (int s = 0; s < int(std::ceil(3.0 * 2.0 / 0.5 / 0.02)); ++s)
            windy.step(velocity, 0.02, scheme, {}, fields);
        const auto [lo, hi] = std::minmax_element(fields.density.begin(), fields.density.end());
        const auto [cold, warm] =
            std::minmax_element(fields.temperature.begin(), fields.temperature.end());
        EXPECT_NEAR(*lo, 0.3, 1e-6);
        EXPECT_NEAR(*hi, 0.3, 1e-6);
        EXPECT_NEAR(*cold, -0.2, 1e-6);
        EXPECT_NEAR(*warm, -0.2, 1e-6);
        EXPECT_EQ(*std::max_element(fields.fuel.begin(), fields.fuel.end()), 0.0);
    }
}

TEST(Wind, SmokeArrivesCleanUpstreamAndLeavesDownstream) {
    const MacGrid grid = MacGrid::fromSpec(windBox(10).grid);
    const std::vector<std::uint8_t> mask(std::size_t(grid.cellCount()), 1);
    for (const AdvectionScheme scheme :
         {AdvectionScheme::SemiLagrangian, AdvectionScheme::MacCormack}) {
        for (const Vec3 u : {Vec3{1.0, 0.0, 0.0}, Vec3{-0.5, 0.7, 0.0}}) {
            reference::SmokeAdvection still(grid, 1, mask), windy(grid, 1, mask);
            windy.setWind(WindSpec{u});
            std::vector<double> velocity(std::size_t(grid.faceTotal()), 0.0);
            addWind(grid, WindSpec{u}, velocity);
            // A box full of smoke is flushed: once the air has crossed it three times (the fronts'
            // numerical tails gone), none is left.
            std::vector<double> full(mask.size(), 1.0), kept = full;
            const double crossing = 2.0 / std::abs(u[0]);  // along x, the longer way out
            const int steps = int(std::ceil(3.0 * crossing / 0.02));
            for (int s = 0; s < steps; ++s) {
                full = windy.advect(velocity, full, 0.02, scheme);
                kept = still.advect(velocity, kept, 0.02, scheme);
            }
            EXPECT_LE(windy.mass(full), 1e-6 * 2.0) << "a sealed box's clamp would keep it";
            std::printf("[ measured ] scheme %d, wind (%g, %g): %.1e of the smoke left\n",
                        int(scheme), u[0], u[1], windy.mass(full) / 2.0);
            EXPECT_GE(still.mass(kept), 0.99 * 2.0) << "without setWind the inflow is closed";
            // A puff crosses the downstream side without piling up against it.
            std::vector<double> puff = testing::gaussianBlob(grid, {1.0, 0.5, 0.0}, 0.1);
            double peak = 0.0;
            for (int s = 0; s < steps; ++s) {
                puff = windy.advect(velocity, puff, 0.02, scheme);
                for (const double value : puff) peak = std::max(peak, value);
            }
            EXPECT_LE(peak, 1.0 + 1e-12);
            EXPECT_LE(windy.mass(puff), 1e-6);
        }
    }
}

TEST(Wind, ASolidHoldsTheWindOffAndTheAirGoesRoundIt) {
    SceneSpec scene = windBox(300);
    scene.wind = WindSpec{{1.0, 0.0, 0.0}};
    ObstacleSpec pillar;
    pillar.radius = 0.2;
    pillar.path = {{0.0, {0.7, 0.5, 0.0}}};
    scene.obstacles = {pillar};
    scene.simulation.dt = 0.02;
    Progress quiet = Progress::silent();
    const RunInputs run = prepareRun(scene, computeBasis(scene, quiet));
    ASSERT_TRUE(run.settings.wind.has_value());
    reference::Simulation simulation(run.cache, *run.coefficients, run.settings, run.smokeMask);
    simulation.advanceSteps(5);
    const MacGrid grid = MacGrid::fromSpec(scene.grid);
    const std::vector<double> u = simulation.faceVelocity();
    const auto xFace = [&](double x, double y) {
        return u[std::size_t(
            grid.faceIndex(0, int(std::lround(x / grid.spacing[0])), int(y / grid.spacing[1]), 0))];
    };
    const double inside = xFace(0.75, 0.5), upstream = xFace(0.125, 0.9), beside = xFace(0.75, 0.9);
    EXPECT_LT(std::abs(inside), 0.2) << "the pillar holds the air still";
    EXPECT_GT(upstream, 0.7);
    EXPECT_GT(beside, 1.0) << "the air speeds up round the pillar";
    std::printf("[ measured ] wind 1 past a pillar: u_x %.3f inside, %.3f upstream, %.3f beside\n",
                inside, upstream, beside);
}

}  // namespace
}  // namespace modeflow
