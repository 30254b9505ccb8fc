#include "engine/output/ParticleFrame.h"

#include <cmath>
#include <cstdio>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "engine/output/PlyBytes.h"
#include "engine/output/PlyFrame.h"

namespace modeflow {

std::string particleFrameFileName(std::string_view sceneName, int frame) {
    return plyFrameFileName(std::string(sceneName) + "_particles", frame);
}

void writeParticleFrame(const std::filesystem::path& path, const ParticleFrame& frame) {
    const std::size_t count = frame.position.size() / 3;
    const std::string where = "particle frame " + path.string();
    if (frame.position.size() != 3 * count || frame.velocity.size() != 3 * count)
        throw Error(where + ": positions and velocities are not three values per particle each");
    if (count > std::size_t(INT32_MAX)) throw Error(where + ": more particles than ids");
    const auto left = [&](std::size_t i) {
        const double* v = &frame.velocity[3 * i];
        return std::isnan(frame.position[3 * i]) && v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
    };
    std::size_t written = 0;
    for (std::size_t i = 0; i < count; ++i) written += !left(i);
    char header[384];
    std::snprintf(header, sizeof header,
                  "ply\nformat binary_little_endian 1.0\ncomment creator modeflow\n"
                  "comment frame %d\ncomment time %.17g\ncomment scene_hash %s\n"
                  "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                  "property float vx\nproperty float vy\nproperty float vz\nproperty int id\n"
                  "end_header\n",
                  frame.frame, frame.time, frame.sceneHash.c_str(), written);
    std::string bytes = header;
    bytes.reserve(bytes.size() + written * 28);
    for (std::size_t i = 0; i < count; ++i) {
        if (left(i)) continue;
        for (int a = 0; a < 3; ++a) {
            const double x = frame.position[3 * i + std::size_t(a)];
            const double v = frame.velocity[3 * i + std::size_t(a)];
            if (!std::isfinite(x) || !std::isfinite(v))
                throw Error(where + ": particle " + std::to_string(i) +
                            " has a non-finite value (the run diverged)");
        }
        for (int a = 0; a < 3; ++a) ply::put(bytes, float(frame.position[3 * i + std::size_t(a)]));
        for (int a = 0; a < 3; ++a) ply::put(bytes, float(frame.velocity[3 * i + std::size_t(a)]));
        ply::put(bytes, std::int32_t(i));
    }
    writeFileAtomically(path, bytes, "particle frame");
}

}  // namespace modeflow
