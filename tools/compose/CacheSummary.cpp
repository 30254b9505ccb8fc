#include "tools/compose/CacheSummary.h"

#include <fstream>
#include <limits>

#include "engine/core/Error.h"
#include "engine/core/InputFile.h"
#include "engine/format/CacheFile.h"
#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "precompute/scene/SceneLoader.h"

namespace modeflow {
namespace {

std::vector<double> toStd(const Eigen::VectorXd& v) {
    return {v.data(), v.data() + v.size()};
}

const char* sourceName(BasisSource s) {
    return s == BasisSource::ClosedForm ? "closed-form" : "eigensolve";
}

nlohmann::ordered_json summary(const BasisCache& c, const std::filesystem::path& path) {
    const BasisChecks checks = checkBasis(c);
    const int n = c.grid.dim;
    nlohmann::ordered_json j;
    if (c.kind == BasisKind::Surface) {
        j["kind"] = "surface";
        j["surface"] = {{"vertices", c.surface.mesh.vertices.size()},
                        {"edges", c.surface.edges.size()},
                        {"triangles", c.surface.mesh.triangles.size()}};
        j["dofs"] = {{"edges", c.faces.size()}, {"triangles", c.cells.size()}};
    } else {
        j["kind"] = "grid";
        j["dim"] = n;
        j["resolution"] =
            std::vector<int>(c.grid.resolution.begin(), c.grid.resolution.begin() + n);
        j["bounds_min"] =
            std::vector<double>(c.grid.boundsMin.begin(), c.grid.boundsMin.begin() + n);
        j["bounds_max"] =
            std::vector<double>(c.grid.boundsMax.begin(), c.grid.boundsMax.begin() + n);
        j["periodic"] = std::vector<bool>(c.grid.periodic.begin(), c.grid.periodic.begin() + n);
        std::vector<std::string> open;
        for (int side = 0; side < 2 * n; ++side)
            if (c.grid.open[std::size_t(side)])
                open.push_back(std::string(1, "xyz"[side / 2]) + (side % 2 ? "_max" : "_min"));
        j["open"] = open;
        j["wall"] = sceneKeyword(c.wall);
        j["boundary"] = sceneKeyword(c.boundary);
        j["dofs"] = {{"faces", c.faces.size()}, {"cells", c.cells.size()}};
    }
    j["velocity"] = {{"count", c.velocity.eigenvalues.size()},
                     {"source", sourceName(c.velocity.source)},
                     {"eigenvalues", toStd(c.velocity.eigenvalues)},
                     {"mode_numbers", c.velocity.modeNumbers},
                     {"harmonic", c.velocity.harmonic},
                     {"max_divergence", checks.maxDivergence},
                     {"orthonormality_error", checks.velocityOrthonormality},
                     // Modes the two checks covered: all, or a sample of a large closed-form basis.
                     {"checked_modes", checks.velocityChecked},
                     {"gradient_penalty", c.velocity.penalty}};
    j["scalar"] = {{"count", c.scalar.eigenvalues.size()},
                   {"source", sourceName(c.scalar.source)},
                   {"boundary", c.kind == BasisKind::Surface ? "closed surface"
                                                             : sceneKeyword(c.scalar.boundary)},
                   {"eigenvalues", toStd(c.scalar.eigenvalues)},
                   {"omitted_constants", c.scalar.omittedConstants},
                   {"orthonormality_error", checks.scalarOrthonormality},
                   {"checked_modes", checks.scalarChecked}};
    const auto& co = c.coefficients;
    using Storage = BasisCache::Coefficients::Storage;
    const char* storage = co.storage == Storage::Dense    ? "dense"
                          : co.storage == Storage::Sparse ? "sparse"
                                                          : "none";
    j["coefficients"] = {
        {"storage", storage},
        {"modes", c.velocity.eigenvalues.size()},
        {"stored", co.storage == Storage::Dense ? co.packed.size() : co.value.size()},
        {"quadrature_elements", c.quadrature.curl.rows()},
        {"density", co.density},
        // Only k < j is stored; C[j][i][k] = −C[k][i][j] is implied, so exactly antisymmetric.
        {"antisymmetry_error", 0.0}};
    nlohmann::ordered_json timings = nlohmann::ordered_json::object();
    for (const auto& [stage, seconds] : c.timings) timings[stage] = seconds;
    j["timings"] = timings;
    j["cache"] = {{"path", path.string()},
                  {"bytes", std::filesystem::file_size(path)},
                  {"format_version", kCacheFormatVersion}};
    return j;
}

/// Whether `bytes` read as text: no control characters but tab and line ends (a TOML scene has
/// none; a picture, an archive or a cache has many).
bool isText(std::string_view bytes) {
    for (const unsigned char c : bytes)
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) return false;
    return true;
}

/// Whether `path` is a cache or a scene, told by its first bytes rather than its name, so that
/// "scene.TOML", "scene.txt" and a cache renamed "x.toml" all work.
/// @throw Error for a folder, a device or a file that is neither.
bool isCache(const std::filesystem::path& path) {
    inputFileSize(path, "cache or scene file", std::numeric_limits<std::uintmax_t>::max());
    std::ifstream in(path, std::ios::binary);
    std::string start(4096, '\0');
    in.read(start.data(), std::streamsize(start.size()));
    start.resize(std::size_t(in.gcount()));
    // A .mfbasis file is meant as a cache: readCache says what is wrong with it.
    if (hasCacheMagic(start) || path.extension() == ".mfbasis") return true;
    if (isText(start)) return false;
    throw Error(path.string() +
                " is neither a modeflow basis cache (it lacks the cache's magic) nor a scene "
                "file (TOML text)");
}

}  // namespace

nlohmann::ordered_json cacheSummary(const std::filesystem::path& cacheFile) {
    return summary(readCache(cacheFile), cacheFile);
}

std::filesystem::path inspectedCache(const std::filesystem::path& cacheOrScene,
                                     const std::filesystem::path& cacheDir, Progress& progress) {
    if (isCache(cacheOrScene)) return cacheOrScene;
    return sceneCache(loadScene(cacheOrScene), cacheDir, progress);
}

std::filesystem::path sceneCache(const SceneSpec& scene, const std::filesystem::path& cacheDir,
                                 Progress& progress) {
    return ensureCache(scene, cacheDir, false, progress).path;
}

}  // namespace modeflow
