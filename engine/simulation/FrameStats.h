#pragma once
/// @file FrameStats.h
/// What advancing a simulation by one frame (or a few steps) did, whichever backend ran it.

#include <map>
#include <string>

namespace modeflow {

/// What advancing one frame did.
struct FrameStats {
    int steps = 0;
    int maxIterations = 0;     ///< implicit schemes: most iterations a step took
    int unconvergedSteps = 0;  ///< steps whose implicit solve missed its tolerance
    int substeps = 1;          ///< most modal substeps a step took (the device adapts them)
    int timedSteps = 0;        ///< steps whose device times were measured (Simulation::setTiming)
    /// Steps the device ran as recorded for an earlier step (device::StepRecording::Once).
    int resubmittedSteps = 0;
    /// Device time per stage summed over the timed steps, milliseconds (0 on the CPU reference or
    /// without timestamps): forces (force field + projection), modal step, reconstruction (of
    /// the velocity the smoke moves in), moving obstacles (the velocity their mismatch reads,
    /// their correction, and smoke pushed out of them), advection, particles.
    double forcesMs = 0.0, modalMs = 0.0, reconstructionMs = 0.0, obstaclesMs = 0.0,
           advectionMs = 0.0, particlesMs = 0.0;
    /// The same device time by what ran (vulkan::CommandSequence::dispatchLabels: a kernel's
    /// name with its specialization constants, or the buffer a fill or copy wrote), for
    /// profiles (`bench_closed_form --kernels`).
    std::map<std::string, double> kernelMs;
};

}  // namespace modeflow
