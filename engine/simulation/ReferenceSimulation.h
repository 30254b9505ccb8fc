#pragma once
/// @file ReferenceSimulation.h
/// The CPU, double-precision run of the same chain as Simulation (forces from the smoke, modal
/// step, reconstruction, advection), built from the CPU references of each kernel: what
/// `--device cpu` runs and what the device is compared with.

#include <cstdint>
#include <vector>

#include "engine/dynamics/ModalIntegrator.h"
#include "engine/simulation/Simulator.h"

namespace modeflow {

class ReferenceSimulation final : public Simulator {
public:
    /// Keeps references to `cache` and `coefficients`, which must outlive it.
    /// @throw modeflow::Error for bad settings or a mask of the wrong size.
    ReferenceSimulation(const BasisCache& cache, const StructuralCoefficients& coefficients,
                        SimulationSettings settings, std::vector<std::uint8_t> smokeMask);

    void setVelocity(const Eigen::VectorXd& v) override;
    Eigen::VectorXd velocity() const override { return mVelocity; }
    void restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) override;
    void setSplats(std::span<const ForceSplat> splats) override {
        mSplats.assign(splats.begin(), splats.end());
    }
    FrameStats advanceFrame() override;
    SmokeFields smoke() const override { return mFields; }
    std::vector<double> faceVelocity() const override { return mFaceVelocity; }
    const SimulationSettings& settings() const override { return mSettings; }
    const MacGrid& smokeGrid() const override { return mAdvection.smokeGrid(); }
    double time() const override { return mTime; }

private:
    const BasisCache& mCache;
    SimulationSettings mSettings;
    FluidSystem mSystem;
    ModalIntegrator mIntegrator;
    SmokeAdvection mAdvection;
    std::vector<ForceSplat> mSplats;
    Eigen::VectorXd mVelocity;
    std::vector<double> mFaceVelocity;
    SmokeFields mFields;
    double mTime = 0.0;
};

}  // namespace modeflow
