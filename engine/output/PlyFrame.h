#pragma once
/// @file PlyFrame.h
/// One frame of a surface run as a PLY file (binary little-endian) that Blender, Houdini and
/// MeshLab open: the surface's vertices with the dye (`density`, and as a colour `red green blue`
/// from white to orange so that any viewer shows it) and the velocity (`vx vy vz`), and its
/// triangles (`vertex_indices`). Comments carry the frame, the time and the scene hash.

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "engine/core/TriangleMesh.h"

namespace modeflow {

struct PlyFrame {
    const TriangleMesh* mesh = nullptr;
    std::span<const double> dye;       ///< one value per vertex
    std::span<const double> velocity;  ///< x, y, z per vertex
    double dyeScale = 1.0;             ///< the dye shown at full colour
    int frame = 0;
    double time = 0.0;
    std::string sceneHash;
};

/// NAME_0001.ply.
std::string plyFrameFileName(std::string_view sceneName, int frame);

/// Writes `frame` to `path` atomically (engine/core/AtomicFile.h).
/// @throw modeflow::Error naming the file when a value is not finite (a diverged run), a size does
///        not match the mesh, or it cannot be written.
void writePlyFrame(const std::filesystem::path& path, const PlyFrame& frame);

}  // namespace modeflow
