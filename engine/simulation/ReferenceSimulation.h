#pragma once
/// @file ReferenceSimulation.h
/// The CPU, double-precision run of the same chain as Simulation (forces from the smoke, modal
/// step, reconstruction, advection), built from the CPU references of each kernel: what
/// `--device cpu` runs and what the device is compared with. It also runs MHD (seed §6.3.5),
/// which the device does not: the modal state is then [v; F] (MhdSystem), forces and moving
/// obstacles act on v alone, and the smoke is carried by v.

#include <cstdint>
#include <memory>
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
    Eigen::VectorXd velocity() const override { return mState.head(mModes); }
    void restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) override;
    Eigen::VectorXd magneticField() const override;
    void setMagneticField(const Eigen::VectorXd& f) override;
    void setSplats(std::span<const ForceSplat> splats) override {
        mSplats.assign(splats.begin(), splats.end());
    }
    FrameStats advanceFrame() override;
    SmokeFields smoke() const override { return mFields; }
    std::vector<double> faceVelocity() const override { return mFaceVelocity; }
    std::vector<double> faceMagneticField() const override;
    const SimulationSettings& settings() const override { return mSettings; }
    const MacGrid& smokeGrid() const override { return mAdvection.smokeGrid(); }
    double time() const override { return mTime; }

private:
    const BasisCache& mCache;
    SimulationSettings mSettings;
    int mModes;
    std::unique_ptr<ModalSystem> mSystem;  ///< FluidSystem over v, or MhdSystem over [v; F]
    ModalIntegrator mIntegrator;
    SmokeAdvection mAdvection;
    std::vector<ForceSplat> mSplats;
    Eigen::VectorXd mState;  ///< v, or [v; F] with MHD
    std::vector<double> mFaceVelocity;
    SmokeFields mFields;
    double mTime = 0.0;
    long mStep = 0;  ///< steps since t = 0, for the divergence message
};

}  // namespace modeflow
