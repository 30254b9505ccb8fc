#pragma once
/// @file StepCarry.h
/// What a simulator carries from one step to the next beyond its state (velocity, field, smoke):
/// the starting points its integrator computed in earlier steps, and the device's substep
/// schedule. A checkpoint saves it and a resumed run sets it after Simulator::restore, so that
/// it continues bit for bit on every backend and integrator.

#include <vector>

#include <Eigen/Core>

namespace modeflow {

struct StepCarry {
    /// The linearized rule's held rate (engine/dynamics/ModalIntegrator.h): N values, or empty
    /// when none is held (another scheme, the first step, after a state set from the host).
    Eigen::VectorXd heldRate;
    /// The device midpoint rule's warm start (engine/device/ModalStepper.h): the right-hand sides
    /// R the last converged steps ended with, newest first; none, one or two vectors of the
    /// state's dimension (N, or 2N with MHD).
    std::vector<Eigen::VectorXd> warmRhs;
    /// The device's modal substeps per step now, and the easy steps counted towards halving them
    /// (device::Simulation::advanceSteps); 1 and 0 on the CPU.
    int substeps = 1;
    int easySteps = 0;
};

}  // namespace modeflow
