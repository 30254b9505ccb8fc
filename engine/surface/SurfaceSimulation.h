#pragma once
/// @file SurfaceSimulation.h
/// A surface scene on the CPU reference (SurfaceSimulator.h): the modal velocity advanced by the
/// CPU reference's modal stage (reference::ModalStepper), stirred by splats (SurfaceForce), and
/// the dye it carries (SurfaceDye), in double precision. The reference of
/// device::SurfaceSimulation.

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "engine/reference/ModalStepper.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/simulation/SurfaceSimulator.h"
#include "engine/surface/SurfaceDye.h"
#include "engine/surface/SurfaceForce.h"

namespace modeflow {

class SurfaceSimulation final : public SurfaceSimulator {
public:
    /// Keeps references to `cache` and `coefficients`, which must outlive it.
    /// @throw modeflow::Error as SurfaceDye does, or for settings FluidSystem refuses.
    SurfaceSimulation(const BasisCache& cache, const StructuralCoefficients& coefficients,
                      const SimulationSettings& settings, const Eigen::VectorXd& velocity);

    FrameStats advanceSteps(int steps) override;
    void restore(double time, const Eigen::VectorXd& velocity, const Eigen::VectorXd& dye) override;
    StepCarry carry() const override { return mStepper.carry(); }
    void setCarry(const StepCarry& carry) override { mStepper.setCarry(carry); }

    void setSplats(std::span<const ForceSplat> splats) override;
    void setViscosity(double viscosity) override { mStepper.setViscosity(viscosity); }
    void setIntegrator(Integrator integrator) override { mStepper.setIntegrator(integrator); }

    double time() const override { return mTime; }
    Eigen::VectorXd velocity() const override { return mStepper.velocity(); }
    Eigen::VectorXd dye() const override { return mDye.state(); }

private:
    double mDt;
    reference::ModalStepper mStepper;
    SurfaceDye mDye;
    SurfaceForce mForce;
    double mTime = 0.0;
    long mStep = 0;
};

}  // namespace modeflow
