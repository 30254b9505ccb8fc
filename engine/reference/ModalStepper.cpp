#include "engine/reference/ModalStepper.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"

namespace modeflow::reference {
namespace {

std::string sizeMismatch(const char* what, Eigen::Index given, Eigen::Index expected) {
    return std::string("simulation: ") + what + " of " + std::to_string(given) +
           " values, expected " + std::to_string(expected);
}

}  // namespace

ModalStepper::ModalStepper(const StructuralCoefficients& coefficients,
                           const SimulationSettings& settings)
    : mCoefficients(coefficients), mModes(coefficients.size()) {
    if (settings.mhd && settings.fluid.alpha > 0.0)
        throw Error("simulation: LANS-alpha and MHD cannot be combined");
    rebuild(settings);
    mState = Eigen::VectorXd::Zero(mSystem->dimension());
    mForce = Eigen::VectorXd::Zero(mSystem->dimension());
}

void ModalStepper::rebuild(const SimulationSettings& settings) {
    std::unique_ptr<ModalSystem> system;
    if (settings.mhd)
        system = std::make_unique<MhdSystem>(
            mCoefficients, MhdParameters{settings.fluid.kappaSquared, settings.fluid.viscosity,
                                         settings.magneticDiffusivity});
    else
        system = std::make_unique<FluidSystem>(mCoefficients, settings.fluid);
    auto integrator =
        std::make_unique<ModalIntegrator>(*system, IntegratorSettings{settings.integrator});
    // Nothing changes until both are built; the integrator refers to the system it was made with.
    mIntegrator = std::move(integrator);
    mSystem = std::move(system);
    mSettings = settings;
}

void ModalStepper::setState(const Eigen::VectorXd& x) {
    if (x.size() != mState.size())
        throw Error(sizeMismatch("modal state", x.size(), mState.size()));
    mState = x;
    mIntegrator->dropHeldRate();
}

void ModalStepper::setCarry(const StepCarry& carry) {
    if (!carry.warmRhs.empty() || carry.substeps != 1 || carry.easySteps != 0)
        throw Error(
            "modal step: the CPU reference takes no warm start nor substeps (a device "
            "run's carry)");
    mIntegrator->setHeldRate(carry.heldRate);
}

void ModalStepper::correctVelocity(const Eigen::VectorXd& dv) {
    if (dv.size() != mModes) throw Error(sizeMismatch("velocity correction", dv.size(), mModes));
    mState.head(mModes) += dv;
}

void ModalStepper::setForce(const Eigen::VectorXd& f) {
    if (f.size() != mModes) throw Error(sizeMismatch("modal force", f.size(), mModes));
    mForce.head(mModes) = f;
    // Held modes ([forcing]) keep their amplitude against forces too.
    for (const int k : mSettings.fluid.held) mForce[k] = 0.0;
}

StepReport ModalStepper::step(double h) {
    return mIntegrator->step(mState, h, mForce);
}

void ModalStepper::setIntegrator(Integrator scheme) {
    SimulationSettings settings = mSettings;
    settings.integrator = scheme;
    rebuild(settings);
}

void ModalStepper::setViscosity(double viscosity) {
    SimulationSettings settings = mSettings;
    settings.fluid.viscosity = viscosity;
    rebuild(settings);
}

void ModalStepper::setVelocity(const Eigen::VectorXd& v) {
    if (v.size() != mModes) throw Error(sizeMismatch("velocity", v.size(), mModes));
    mState.head(mModes) = v;
    mIntegrator->dropHeldRate();
}

Eigen::VectorXd ModalStepper::magneticField() const {
    return mSettings.mhd ? Eigen::VectorXd(mState.tail(mModes)) : Eigen::VectorXd();
}

void ModalStepper::setMagneticField(const Eigen::VectorXd& f) {
    if (!mSettings.mhd)
        throw Error("simulation: this run simulates no magnetic field ([simulation].mhd)");
    if (f.size() != mModes) throw Error(sizeMismatch("magnetic field", f.size(), mModes));
    mState.tail(mModes) = f;
    mIntegrator->dropHeldRate();
}

}  // namespace modeflow::reference
