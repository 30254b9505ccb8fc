/// @file LansMhdTest.cpp
/// LANS-α and MHD (seed §6.3.5): analytic Jacobians, and the invariants the midpoint rule must
/// keep to solver tolerance — ½Σ(1 + α²κ²)v², and ½(|v|² + |F|²) with Σ v_i F_i, in the modal
/// system alone and in the CPU reference simulation of a whole MHD scene.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/reference/Simulation.h"
#include "engine/reference/VelocityReconstruction.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/SharedRuns.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

using testing::randomDense;
using testing::randomVector;
using testing::shapedKappaSquared;

/// Largest relative difference between the analytic Jacobian and central differences (exact
/// for a quadratic R, up to round-off).
double jacobianError(const ModalSystem& system, const Eigen::VectorXd& x) {
    Eigen::VectorXd r, plus, minus;
    Eigen::MatrixXd jac;
    system.linearize(x, r, jac);
    system.rhs(x, plus);
    double worst = (r - plus).norm() / plus.norm();
    const double eps = 1e-6;
    for (int l = 0; l < x.size(); ++l) {
        Eigen::VectorXd dx = Eigen::VectorXd::Zero(x.size());
        dx[l] = eps;
        system.rhs(x + dx, plus);
        system.rhs(x - dx, minus);
        worst = std::max(worst, ((plus - minus) / (2 * eps) - jac.col(l)).norm() / jac.norm());
    }
    return worst;
}

/// A step with h·|R(x)|/|Mx| = 0.3.
double largeStep(const ModalSystem& system, const Eigen::VectorXd& x) {
    Eigen::VectorXd r;
    system.rhs(x, r);
    return 0.3 * system.mass().cwiseProduct(x).norm() / r.norm();
}

TEST(Lans, JacobianIsAnalytic) {
    const DenseCoefficients c = randomDense(12, 501);
    const FluidSystem system(c, {shapedKappaSquared(12), 0.0, 0.07});
    EXPECT_LT(jacobianError(system, randomVector(12, 502)), 1e-8);
}

TEST(Lans, MidpointConservesTheFilteredEnergy) {
    const int n = 40;
    const DenseCoefficients c = randomDense(n, 503);
    const Eigen::VectorXd k2 = shapedKappaSquared(n);
    const double alpha = 0.05;
    const FluidSystem system(c, {k2, 0.0, alpha});
    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd v = randomVector(n, 504);
    const double h = largeStep(system, v), lans0 = lansEnergy(v, k2, alpha), plain0 = energy(v);
    double worst = 0.0, plainChange = 0.0;
    int maxIterations = 0;
    for (int s = 0; s < 3000; ++s) {
        maxIterations = std::max(maxIterations, midpoint.step(v, h).iterations);
        worst = std::max(worst, std::abs(lansEnergy(v, k2, alpha) / lans0 - 1.0));
        plainChange = std::max(plainChange, std::abs(energy(v) / plain0 - 1.0));
    }
    EXPECT_LE(worst, 1e-10);
    EXPECT_LE(maxIterations, 8);
    EXPECT_GT(plainChange, 1e-3) << "½|v|² is not the invariant, so it must move";
}

TEST(Lans, ForcesActOnTheMomentum) {
    const int n = 6;
    const DenseCoefficients zero(n, std::vector<double>(packedSize(n), 0.0));
    const Eigen::VectorXd k2 = shapedKappaSquared(n);
    const FluidSystem system(zero, {k2, 0.0, 0.1});
    const Eigen::VectorXd v0 = randomVector(n, 505), f = randomVector(n, 506);
    for (Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint,
                              Integrator::Trapezoidal, Integrator::Linearized}) {
        ModalIntegrator integrator(system, {scheme});
        Eigen::VectorXd v = v0;
        for (int s = 0; s < 20; ++s) integrator.step(v, 0.1, f);
        const Eigen::VectorXd expected = v0 + 2.0 * f.cwiseQuotient(system.mass());
        EXPECT_LT((v - expected).norm() / expected.norm(), 1e-13) << sceneKeyword(scheme);
    }
}

TEST(Mhd, JacobianIsAnalytic) {
    const DenseCoefficients c = randomDense(10, 601);
    const MhdSystem system(c);
    EXPECT_LT(jacobianError(system, system.state(randomVector(10, 602), randomVector(10, 603))),
              1e-8);
}

TEST(Mhd, MidpointConservesEnergyAndCrossHelicity) {
    const int n = 30;
    const DenseCoefficients c = randomDense(n, 604);
    const MhdSystem system(c);
    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd x = system.state(randomVector(n, 605), 0.7 * randomVector(n, 606));
    const double h = largeStep(system, x), e0 = energy(x);
    const double scale = x.head(n).norm() * x.tail(n).norm();
    const double h0 = crossHelicity(x.head(n), x.tail(n));
    double worstE = 0.0, worstH = 0.0, fieldChange = 0.0;
    int maxIterations = 0;
    const Eigen::VectorXd f0 = x.tail(n);
    for (int s = 0; s < 3000; ++s) {
        maxIterations = std::max(maxIterations, midpoint.step(x, h).iterations);
        worstE = std::max(worstE, std::abs(energy(x) / e0 - 1.0));
        worstH = std::max(worstH, std::abs(crossHelicity(x.head(n), x.tail(n)) - h0) / scale);
        fieldChange = std::max(fieldChange, (x.tail(n) - f0).norm() / f0.norm());
    }
    EXPECT_LE(worstE, 1e-10);
    EXPECT_LE(worstH, 1e-10) << "relative to |v||F|";
    EXPECT_LE(maxIterations, 8);
    EXPECT_GT(fieldChange, 0.5) << "the field must actually be advected";
}

TEST(Kelvin, MidpointConservesTheSpectralCirculationOfAnAdvectedLoop) {
    // Appendix C.3: a loop Γ = Σ γ_i ⋆A_i carried by the flow, γ̇_k = Σ_ij γ_i v_j C[j][k][i],
    // keeps its circulation ⟨A, Γ⟩ = Σ v_i γ_i while the Euler flow v evolves on its own.
    const int n = 30;
    const DenseCoefficients c = randomDense(n, 607);
    MhdParameters passive;
    passive.lorentzForce = false;
    const MhdSystem system(c, passive);
    EXPECT_LT(jacobianError(system, system.state(randomVector(n, 608), randomVector(n, 609))),
              1e-8);
    ModalIntegrator midpoint(system, {Integrator::Midpoint});
    Eigen::VectorXd x = system.state(randomVector(n, 610), randomVector(n, 611));
    const Eigen::VectorXd v0 = x.head(n), loop0 = x.tail(n);
    // A passive loop is stretched exponentially (only its circulation is conserved), so a few
    // turnovers, not the MHD test's 3000 steps.
    const double h = largeStep(system, x), e0 = energy(x.head(n));
    const double circulation0 = crossHelicity(x.head(n), x.tail(n));
    const double scale = x.head(n).norm() * x.tail(n).norm();
    double worstCirculation = 0.0, worstEnergy = 0.0, loopChange = 0.0;
    for (int s = 0; s < 40; ++s) {
        midpoint.step(x, h);
        worstCirculation = std::max(
            worstCirculation, std::abs(crossHelicity(x.head(n), x.tail(n)) - circulation0) / scale);
        worstEnergy = std::max(worstEnergy, std::abs(energy(x.head(n)) / e0 - 1.0));
        loopChange = std::max(loopChange, (x.tail(n) - loop0).norm() / loop0.norm());
    }
    EXPECT_LE(worstCirculation, 1e-10) << "relative to |v||γ|";
    EXPECT_LE(worstEnergy, 1e-10) << "the loop must not act on the flow";
    EXPECT_GT(loopChange, 0.5) << "the loop must actually be advected";

    // The velocity alone follows the Euler flow: the same steps without the loop agree.
    const FluidSystem euler(c);
    ModalIntegrator eulerStep(euler, {Integrator::Midpoint});
    Eigen::VectorXd v = v0;
    for (int s = 0; s < 40; ++s) eulerStep.step(v, h);
    EXPECT_LE((v - x.head(n)).norm(), 1e-9 * v.norm());
}

TEST(Mhd, WithoutFieldItIsTheEulerFlow) {
    const int n = 15;
    const DenseCoefficients c = randomDense(n, 607);
    const MhdSystem mhd(c);
    const FluidSystem euler(c);
    const Eigen::VectorXd v0 = randomVector(n, 608);
    ModalIntegrator a(mhd), b(euler);
    Eigen::VectorXd x = mhd.state(v0, Eigen::VectorXd::Zero(n)), v = v0;
    for (int s = 0; s < 50; ++s) {
        a.step(x, 0.01);
        b.step(v, 0.01);
    }
    EXPECT_LT((x.head(n) - v).norm() / v.norm(), 1e-12);
    EXPECT_EQ(x.tail(n).norm(), 0.0);
}

TEST(Mhd, SparseStorageGivesTheSameTrajectory) {
    const int n = 20;
    const DenseCoefficients dense = randomDense(n, 609, 0.1);
    const SparseCoefficients sparse = SparseCoefficients::fromDense(dense);
    const MhdSystem a(dense), b(sparse);
    Eigen::VectorXd x = a.state(randomVector(n, 610), randomVector(n, 611)), y = x;
    ModalIntegrator ia(a), ib(b);
    for (int s = 0; s < 20; ++s) {
        ia.step(x, 0.02);
        ib.step(y, 0.02);
    }
    EXPECT_LT((x - y).norm() / x.norm(), 1e-12);
}

TEST(Mhd, BadInputThrows) {
    const DenseCoefficients c = randomDense(5, 612);
    const MhdSystem system(c);
    EXPECT_THROW(system.state(Eigen::VectorXd::Ones(5), Eigen::VectorXd::Ones(4)), Error);
    EXPECT_THROW(MhdSystem(c, {Eigen::VectorXd::Ones(5), 0.0, -1.0}), Error);
    EXPECT_THROW(MhdSystem(c, {Eigen::VectorXd(), 0.0, 1.0}), Error);
    EXPECT_THROW(crossHelicity(Eigen::VectorXd::Ones(5), Eigen::VectorXd::Ones(4)), Error);
}

/// A unit disk at 24² with 12 modes and a smoke source, for the MHD runs of the reference
/// simulation (the chain `modeflow run --device cpu` runs).
const RunInputs& mhdDisk() {
    static const RunInputs disk = [] {
        SceneSpec scene = testing::unitBallScene(2, 24, 12, 0);
        scene.name = "mhd";
        scene.simulation.mhd = true;
        scene.output.stepsPerFrame = 20;
        SourceSpec source;
        source.shape = testing::ball({0.0, 0.0, 0.0}, 0.3);
        scene.sources = {source};
        return testing::sharedRun(scene);
    }();
    return disk;
}

TEST(MhdSimulation, ReferenceRunKeepsEnergyAndCrossHelicity) {
    const RunInputs& disk = mhdDisk();
    const int n = disk.coefficients->size();
    const SimulationSettings& settings = disk.settings;
    ASSERT_TRUE(settings.mhd);
    reference::Simulation simulation(disk.cache, *disk.coefficients, settings, disk.smokeMask);
    const Eigen::VectorXd v = randomVector(n, 601), f = 0.7 * randomVector(n, 602);
    simulation.setVelocity(v);
    simulation.setMagneticField(f);
    const double e0 = 0.5 * (v.squaredNorm() + f.squaredNorm()), h0 = crossHelicity(v, f);
    for (int frame = 0; frame < 10; ++frame) simulation.advanceFrame();  // 200 midpoint steps
    const Eigen::VectorXd v1 = simulation.velocity(), f1 = simulation.magneticField();
    const double e1 = 0.5 * (v1.squaredNorm() + f1.squaredNorm()), h1 = crossHelicity(v1, f1);
    std::cout << "MHD reference run, 200 midpoint steps: energy drift " << e1 / e0 - 1.0
              << ", cross helicity drift " << (h1 - h0) / std::abs(h0) << "\n";
    EXPECT_LE(std::abs(e1 / e0 - 1.0), 1e-6);
    EXPECT_LE(std::abs(h1 - h0), 1e-6 * std::abs(h0));
    // The field moved with the flow and exchanged energy with it.
    EXPECT_GT((f1 - f).norm(), 0.1 * f.norm());
    EXPECT_GT(std::abs(f1.squaredNorm() - f.squaredNorm()), 1e-3 * f.squaredNorm());
    EXPECT_EQ(simulation.faceMagneticField(), reference::reconstructFaceField(disk.cache, f1));
    EXPECT_EQ(simulation.faceVelocity(), reference::reconstructFaceField(disk.cache, v1));
}

TEST(MhdSimulation, PlainFluidRunsRefuseAField) {
    const RunInputs& disk = mhdDisk();
    SimulationSettings fluid = disk.settings;
    fluid.mhd = false;
    reference::Simulation simulation(disk.cache, *disk.coefficients, fluid, disk.smokeMask);
    EXPECT_EQ(simulation.magneticField().size(), 0);
    EXPECT_TRUE(simulation.faceMagneticField().empty());
    EXPECT_THROW(simulation.setMagneticField(Eigen::VectorXd::Zero(12)), Error);
}

}  // namespace
}  // namespace modeflow
