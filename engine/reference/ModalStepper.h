#pragma once
/// @file ModalStepper.h
/// The modal step on the CPU, in double precision: the state v (or [v; F] with MHD), the
/// model it follows (FluidSystem: Euler, Navier–Stokes, LANS-α; MhdSystem) and a ModalIntegrator
/// of any scheme. The reference of engine/device/ModalStepper, and the modal stage of
/// reference::Simulation.

#include <memory>

#include <Eigen/Core>

#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/ModalSystem.h"
#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/simulation/ModalStepping.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/simulation/StepCarry.h"

namespace modeflow::reference {

class ModalStepper final : public ModalStepping {
public:
    /// The model and scheme of `settings` (fluid parameters, mhd, magnetic diffusivity,
    /// integrator); keeps a reference to `coefficients`, which must outlive the stepper. The
    /// state starts at zero.
    /// @throw modeflow::Error for LANS-α with MHD, or parameters the model refuses.
    ModalStepper(const StructuralCoefficients& coefficients, const SimulationSettings& settings);

    int modeCount() const { return mModes; }
    /// N, or 2N with MHD.
    int dimension() const { return mSystem->dimension(); }

    void setState(const Eigen::VectorXd& x) override;
    Eigen::VectorXd state() const override { return mState; }
    /// The modal force on v (N values), held constant over the following steps; with MHD the
    /// field's half of the force stays 0.
    /// @throw modeflow::Error on a wrong size.
    void setForce(const Eigen::VectorXd& f);
    StepReport step(double h) override;

    /// The scheme of the following steps.
    void setIntegrator(Integrator scheme);
    /// A new viscosity for the following steps.
    /// @throw modeflow::Error for a viscosity the model refuses.
    void setViscosity(double viscosity);

    /// v (the first N entries of the state), which forces and reconstruction see.
    Eigen::VectorXd velocity() const { return mState.head(mModes); }
    /// A new v (or state, or F): the integrator's held rate is dropped (ModalIntegrator.h).
    void setVelocity(const Eigen::VectorXd& v);
    /// v += dv within a run (moving obstacles): the held rate stays.
    void correctVelocity(const Eigen::VectorXd& dv);
    /// What the steps carry (Simulator::carry): the linearized rule's held rate
    /// (ModalIntegrator::heldRate) alone, as the CPU has no warm start nor substeps; and its
    /// restore. @throw modeflow::Error for a warm start or substeps (a device run's carry), or a
    /// rate the integrator refuses.
    StepCarry carry() const { return {mIntegrator->heldRate(), {}, 1, 0}; }
    void setCarry(const StepCarry& carry);
    /// F; empty without MHD.
    Eigen::VectorXd magneticField() const;
    void setMagneticField(const Eigen::VectorXd& f);
    bool hasMagneticField() const { return mSettings.mhd; }

private:
    /// Builds the model and integrator of `settings`, and only then takes them.
    void rebuild(const SimulationSettings& settings);

    const StructuralCoefficients& mCoefficients;
    SimulationSettings mSettings;
    int mModes;
    std::unique_ptr<ModalSystem> mSystem;  ///< FluidSystem over v, or MhdSystem over [v; F]
    std::unique_ptr<ModalIntegrator> mIntegrator;
    Eigen::VectorXd mState;
    Eigen::VectorXd mForce;
};

}  // namespace modeflow::reference
