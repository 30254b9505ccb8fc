#include "tools/compose/SmokeMask.h"

#include <string>

#include "engine/core/BinaryCodec.h"
#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/format/SmokeMaskFile.h"
#include "precompute/geometry/FluidMask.h"

namespace modeflow {

std::vector<std::uint8_t> smokeMaskOf(const SceneSpec& scene, const BasisCache& cache,
                                      const std::filesystem::path& cachePath, Progress& progress) {
    const int scale = scene.smoke.resolutionScale;
    if (!fluidMaskNeedsDomain(scene, scale)) return fluidMask(scene, cache, scale);
    const std::filesystem::path path = smokeMaskPath(cachePath, scale);
    const std::uint64_t key = fnv1a64(cache.key);
    const auto cells = std::size_t(MacGrid::fromSpec(cache.grid).refined(scale).cellCount());
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) {
        try {
            return readSmokeMask(path, key, scale, cells);
        } catch (const Error& e) {
            progress.note(std::string(e.what()) + "; rebuilding it");
        }
    }
    progress.begin("smoke mask at scale " + std::to_string(scale));
    std::vector<std::uint8_t> mask = fluidMask(scene, cache, scale);
    writeSmokeMask(path, key, scale, mask);
    progress.end();
    return mask;
}

}  // namespace modeflow
