#pragma once
/// @file ParticleFrame.h
/// One frame of a run's `[[particles]]` as a binary little-endian PLY point cloud that Blender,
/// Houdini and MeshLab open: per particle `x y z vx vy vz` (float) and `id` (int: its place in
/// emission order, the same particle in every frame). Comments carry the frame, the time and the
/// scene hash.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace modeflow {

struct ParticleFrame {
    std::span<const double> position;  ///< x, y, z per particle
    std::span<const double> velocity;  ///< x, y, z per particle
    int frame = 0;
    double time = 0.0;
    std::string sceneHash;
};

/// NAME_particles_0001.ply.
std::string particleFrameFileName(std::string_view sceneName, int frame);

/// Writes `frame` to `path` atomically (engine/core/AtomicFile.h), each particle with its place
/// as its `id`. A particle that has left through an open side (its position NaN, its velocity 0:
/// engine/simulation/ParticleMotion.h) is left out; the others keep their ids.
/// @throw modeflow::Error naming the file when another value is not finite (a diverged run), the
///        sizes differ, or it cannot be written.
void writeParticleFrame(const std::filesystem::path& path, const ParticleFrame& frame);

}  // namespace modeflow
