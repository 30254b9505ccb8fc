#pragma once
/// @file Checkpoint.h
/// The state a run resumes from (`modeflow run --resume`): written after every frame, beside the
/// frames. It holds the modal velocity, the modal magnetic field (MHD runs) and the smoke exactly
/// as the simulator holds them (device floats widen to doubles and narrow back without loss), so a
/// resumed run continues bit for bit.
///
/// Layout (little-endian): magic "MODEFLOW-RESUME\0" | u32 version (6) | u32 frame | u64 run
/// hash | f64 time | u64 N | N × f64 velocity | u64 M | M × f64 magnetic field (M = 0 without
/// MHD) | the step carry (StepCarry.h): u64 R | R × f64 held rate (R = 0 or N) | u64 W (0, 1 or
/// 2) | W × (u64 D | D × f64 warm-start R, D = N + M) | u32 substeps | u32 easy steps | u64
/// cells | cells × f64 density | cells × f64 temperature | u64 P | 3P × f64 particle positions |
/// u64 3P | 3P × f64 particle velocities | u64 P | P × u8 particle sets | u64 XXH3 checksum
/// (Checksum.h) of everything before it.

#include <cstdint>
#include <filesystem>

#include <Eigen/Core>

#include "engine/simulation/Particles.h"
#include "engine/simulation/SmokeFields.h"
#include "engine/simulation/StepCarry.h"

namespace modeflow {

struct Checkpoint {
    int frame = 0;              ///< frames completed
    double time = 0.0;          ///< simulated time after them
    std::uint64_t runHash = 0;  ///< what shaped the run (scene, device kind, options)
    Eigen::VectorXd velocity;
    Eigen::VectorXd magnetic;  ///< F of an MHD run; empty otherwise
    StepCarry carry;           ///< what the steps carry beyond the state (Simulator::carry)
    SmokeFields smoke;
    Particles particles;  ///< Simulator::particles
};

/// Writes to a temporary file beside `path` and renames it over `path`.
/// @throw modeflow::Error naming the file when it cannot be written (no partial file is left).
void writeCheckpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);

/// @throw modeflow::Error saying why the file cannot be used (missing, truncated, corrupt, or a
/// value no run can continue from: a non-finite state or smoke).
Checkpoint readCheckpoint(const std::filesystem::path& path);

}  // namespace modeflow
