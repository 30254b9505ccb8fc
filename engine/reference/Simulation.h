#pragma once
/// @file Simulation.h
/// The whole step on the CPU, in double precision: forces from the smoke, the modal step,
/// reconstruction, moving obstacles, advection, smoke pushed out of solids, particles — each stage
/// this folder's reference of the device stage of the same name. What `--device cpu` runs and what
/// device::Simulation is compared with. It also runs MHD (seed §6.3.5): the modal state is then [v;
/// F] (MhdSystem), forces and moving obstacles act on v alone, and the smoke is carried by v.

#include <cstdint>
#include <vector>

#include "engine/basis/VelocityBasis.h"
#include "engine/reference/ModalStepper.h"
#include "engine/reference/ParticleAdvection.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/reference/SmokeDisplacement.h"
#include "engine/simulation/InflowPatch.h"
#include "engine/simulation/Simulator.h"

namespace modeflow::reference {

class Simulation final : public Simulator {
public:
    /// Keeps references to `cache` and `coefficients`, which must outlive it.
    /// @throw modeflow::Error for bad settings or a mask of the wrong size.
    Simulation(const BasisCache& cache, const StructuralCoefficients& coefficients,
               SimulationSettings settings, std::vector<std::uint8_t> smokeMask);

    void setVelocity(const Eigen::VectorXd& v) override { mStepper.setVelocity(v); }
    Eigen::VectorXd velocity() const override { return mStepper.velocity(); }
    StepCarry carry() const override { return mStepper.carry(); }
    void setCarry(const StepCarry& carry) override { mStepper.setCarry(carry); }
    void restore(double time, const Eigen::VectorXd& v, const SmokeFields& smoke) override;
    Eigen::VectorXd magneticField() const override { return mStepper.magneticField(); }
    void setMagneticField(const Eigen::VectorXd& f) override { mStepper.setMagneticField(f); }
    Particles particles() const override { return mParticles.particles(); }
    void setParticles(const Particles& particles) override { mParticles.restore(particles); }
    void setSplats(std::span<const ForceSplat> splats) override {
        mSplats.assign(splats.begin(), splats.end());
    }
    void setObstacles(std::vector<MovingObstacle> obstacles) override;
    void setEmitters(std::vector<SmokeEmitter> emitters) override;
    void setViscosity(double viscosity) override;
    void setIntegrator(Integrator integrator) override;
    FrameStats advanceSteps(int steps) override;
    SmokeFields smoke() const override { return mFields; }
    std::vector<double> faceVelocity() const override { return mFaceVelocity; }
    std::vector<double> faceMagneticField() const override;
    const SimulationSettings& settings() const override { return mSettings; }
    const MacGrid& smokeGrid() const override { return mAdvection.smokeGrid(); }
    double time() const override { return mTime; }

private:
    /// mFaceVelocity = Ψ v, plus the wind's B.
    void reconstructAirVelocity();

    const BasisCache& mCache;
    VelocityBasis mBasis;  ///< Ψ v and Ψᵀ q: the columns, or a closed-form basis's transforms
    SimulationSettings mSettings;
    ModalStepper mStepper;
    SmokeAdvection mAdvection;
    SmokeDisplacement mDisplacement;
    ParticleAdvection mParticles;
    std::vector<ForceSplat> mSplats;
    std::vector<double> mFaceVelocity;
    /// A wind's base flow B on the faces (addWind, made once; empty without a wind).
    std::vector<double> mWindField;
    ActiveInflowSet mActiveInflows;  ///< the inflows the smoke's ghosts hold now
    SmokeFields mFields;
    double mTime = 0.0;
    long mStep = 0;  ///< steps since t = 0, for the divergence message
};

}  // namespace modeflow::reference
