#pragma once
/// @file ModalStepping.h
/// The reduced dynamics alone, stepped from the host (`modeflow modes`): the modal state and
/// one step of the chosen integrator at a time, on either backend (reference::ModalStepper,
/// device::ModalStepper).

#include <Eigen/Core>

#include "engine/dynamics/StepReport.h"

namespace modeflow {

class ModalStepping {
public:
    virtual ~ModalStepping() = default;

    /// The state: v, or [v; F] with MHD.
    /// @throw modeflow::Error on a wrong size.
    virtual void setState(const Eigen::VectorXd& x) = 0;
    virtual Eigen::VectorXd state() const = 0;
    /// One unforced step of size h; the report's iterations are Newton iterations on the CPU
    /// reference and fixed-point iterations on a device.
    virtual StepReport step(double h) = 0;
};

}  // namespace modeflow
