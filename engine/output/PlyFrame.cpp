/// @file PlyFrame.cpp

#include "engine/output/PlyFrame.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "engine/output/PlyBytes.h"

namespace modeflow {

using ply::put;

std::string plyFrameFileName(std::string_view sceneName, int frame) {
    if (sceneName.empty()) throw Error("a PLY frame file needs a scene name");
    if (frame < 0) throw Error("frame numbers start at 0, got " + std::to_string(frame));
    char digits[16];
    std::snprintf(digits, sizeof digits, "%04d", frame);
    return std::string(sceneName) + "_" + digits + ".ply";
}

void writePlyFrame(const std::filesystem::path& path, const PlyFrame& frame) {
    const TriangleMesh& mesh = *frame.mesh;
    const std::size_t vertices = mesh.vertices.size();
    const std::string where = "PLY frame " + path.string();
    if (frame.dye.size() != vertices || frame.velocity.size() != 3 * vertices)
        throw Error(where + ": the dye or the velocity does not have one value per vertex");
    for (std::size_t i = 0; i < frame.dye.size(); ++i)
        if (!std::isfinite(frame.dye[i]) || !std::isfinite(frame.velocity[3 * i]) ||
            !std::isfinite(frame.velocity[3 * i + 1]) || !std::isfinite(frame.velocity[3 * i + 2]))
            throw Error(where + ": vertex " + std::to_string(i + 1) +
                        " has a non-finite value (the run diverged)");
    char header[512];
    std::snprintf(
        header, sizeof header,
        "ply\nformat binary_little_endian 1.0\ncomment creator modeflow\ncomment frame %d\n"
        "comment time %.17g\ncomment scene_hash %s\nelement vertex %zu\nproperty float x\n"
        "property float y\nproperty float z\nproperty float vx\nproperty float vy\nproperty float "
        "vz\n"
        "property float density\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
        "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
        frame.frame, frame.time, frame.sceneHash.c_str(), vertices, mesh.triangles.size());
    std::string bytes = header;
    bytes.reserve(bytes.size() + vertices * 31 + mesh.triangles.size() * 13);
    for (std::size_t v = 0; v < vertices; ++v) {
        for (double x : mesh.vertices[v]) put(bytes, float(x));
        for (int k = 0; k < 3; ++k) put(bytes, float(frame.velocity[3 * v + std::size_t(k)]));
        put(bytes, float(frame.dye[v]));
        // White where there is no dye, towards orange (255, 128, 26) at dyeScale.
        const double a = std::clamp(frame.dye[v] / frame.dyeScale, 0.0, 1.0);
        put(bytes, std::uint8_t(std::lround(255.0)));
        put(bytes, std::uint8_t(std::lround(255.0 - a * 127.0)));
        put(bytes, std::uint8_t(std::lround(255.0 - a * 229.0)));
    }
    for (const auto& t : mesh.triangles) {
        put(bytes, std::uint8_t(3));
        for (int v : t) put(bytes, std::int32_t(v));
    }
    writeFileAtomically(path, bytes, "PLY frame");
}

}  // namespace modeflow
