#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/format/CacheFile.h"
#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/modeflow/Commands.h"

namespace modeflow::cli {
namespace {

std::vector<double> toStd(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

nlohmann::ordered_json summarize(const BasisCache& c, const std::filesystem::path& path) {
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
        j["resolution"] = std::vector<int>(c.grid.resolution.begin(), c.grid.resolution.begin() + n);
        j["bounds_min"] = std::vector<double>(c.grid.boundsMin.begin(), c.grid.boundsMin.begin() + n);
        j["bounds_max"] = std::vector<double>(c.grid.boundsMax.begin(), c.grid.boundsMax.begin() + n);
        j["wall"] = sceneKeyword(c.wall);
        j["boundary"] = sceneKeyword(c.boundary);
        j["dofs"] = {{"faces", c.faces.size()}, {"cells", c.cells.size()}};
    }
    j["velocity"] = {{"count", c.velocity.eigenvalues.size()},
                     {"eigenvalues", toStd(c.velocity.eigenvalues)},
                     {"mode_numbers", c.velocity.modeNumbers},
                     {"harmonic", c.velocity.harmonic},
                     {"max_divergence", checks.maxDivergence},
                     {"orthonormality_error", checks.velocityOrthonormality},
                     {"gradient_penalty", c.velocity.penalty}};
    j["scalar"] = {{"count", c.scalar.eigenvalues.size()},
                   {"boundary", c.kind == BasisKind::Surface ? "closed surface" : sceneKeyword(c.scalar.boundary)},
                   {"eigenvalues", toStd(c.scalar.eigenvalues)},
                   {"omitted_constants", c.scalar.omittedConstants},
                   {"orthonormality_error", checks.scalarOrthonormality}};
    const auto& co = c.coefficients;
    const bool dense = co.storage == BasisCache::Coefficients::Storage::Dense;
    j["coefficients"] = {
        {"storage", dense ? "dense" : "sparse"},
        {"modes", c.velocity.modes.cols()},
        {"stored", dense ? co.packed.size() : co.value.size()},
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

void printText(const nlohmann::ordered_json& j) {
    if (j["kind"] == "surface") {
        const auto& m = j["surface"];
        std::cout << "surface    " << m["vertices"] << " vertices, " << m["edges"] << " edges, "
                  << m["triangles"] << " triangles\n"
                  << "dofs       " << j["dofs"]["edges"] << " edge fluxes, " << j["dofs"]["triangles"]
                  << " triangles\n";
    } else {
        std::cout << "grid       " << j["dim"] << "D " << j["resolution"].dump() << ", "
                  << j["boundary"].get<std::string>() << ", " << j["wall"].get<std::string>() << "\n"
                  << "dofs       " << j["dofs"]["faces"] << " faces, " << j["dofs"]["cells"]
                  << " cells\n";
    }
    auto list = [](const nlohmann::ordered_json& values) {
        std::ostringstream s;
        s << std::setprecision(6);
        size_t i = 0;
        for (const auto& v : values) {
            if (i == 8) {
                s << " ...";
                break;
            }
            s << (i++ ? ", " : "") << v.get<double>();
        }
        return s.str();
    };
    const auto& v = j["velocity"];
    std::cout << "velocity   " << v["count"] << " modes (" << v["harmonic"] << " harmonic), κ² = "
              << list(v["eigenvalues"]) << "\n"
              << "           max divergence " << v["max_divergence"].get<double>()
              << ", orthonormality error " << v["orthonormality_error"].get<double>() << "\n";
    const auto& s = j["scalar"];
    std::cout << "scalar     " << s["count"] << " " << s["boundary"].get<std::string>()
              << " modes, μ² = " << list(s["eigenvalues"]) << "\n";
    const auto& co = j["coefficients"];
    std::cout << "C          " << co["storage"].get<std::string>() << ", " << co["stored"]
              << " stored entries (density " << co["density"].get<double>() << ")\n";
    std::cout << "timings   ";
    for (const auto& [stage, seconds] : j["timings"].items())
        std::cout << " " << stage << " " << std::fixed << std::setprecision(2)
                  << seconds.get<double>() << " s";
    std::cout << std::defaultfloat << "\ncache      " << j["cache"]["path"].get<std::string>()
              << " (" << j["cache"]["bytes"] << " bytes)\n";
}

}  // namespace

Command addInspect(CLI::App& app) {
    struct Options {
        std::string target;
        std::optional<std::string> cacheDir;
        bool json = false;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "inspect", "Summarize a cache file, or a scene's cache (precomputed on a miss)");
    sub->add_option("CACHE_OR_SCENE", opts->target, "a .mfbasis cache file or a .toml scene")
        ->required();
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder used for a scene");
    sub->add_flag("--json", opts->json, "print one JSON object (keys in the README)");
    return [sub, opts]() {
        if (!*sub) return -1;
        std::filesystem::path path = opts->target;
        if (path.extension() == ".toml") {
            const SceneSpec scene = loadScene(path);
            Progress progress = Progress::toStderr();
            path = ensureCache(scene, resolveCacheDir(opts->cacheDir), false, progress).path;
        }
        const nlohmann::ordered_json j = summarize(readCache(path), path);
        if (opts->json) std::cout << j.dump() << std::endl;
        else printText(j);
        return 0;
    };
}

}  // namespace modeflow::cli
