#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>

#include <nlohmann/json.hpp>

#include "engine/core/InputFile.h"
#include "engine/format/CacheFile.h"
#include "precompute/BasisChecks.h"
#include "precompute/Precompute.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/modeflow/Commands.h"

namespace modeflow::cli {
namespace {

std::vector<double> toStd(const Eigen::VectorXd& v) {
    return {v.data(), v.data() + v.size()};
}

const char* sourceName(BasisSource s) {
    return s == BasisSource::ClosedForm ? "closed-form" : "eigensolve";
}

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
        j["resolution"] =
            std::vector<int>(c.grid.resolution.begin(), c.grid.resolution.begin() + n);
        j["bounds_min"] =
            std::vector<double>(c.grid.boundsMin.begin(), c.grid.boundsMin.begin() + n);
        j["bounds_max"] =
            std::vector<double>(c.grid.boundsMax.begin(), c.grid.boundsMax.begin() + n);
        j["periodic"] = std::vector<bool>(c.grid.periodic.begin(), c.grid.periodic.begin() + n);
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

/// ", periodic x, z" for the periodic axes; nothing when every axis has walls.
std::string periodicAxes(const nlohmann::ordered_json& flags) {
    std::string axes;
    for (std::size_t a = 0; a < flags.size(); ++a)
        if (flags[a].get<bool>())
            axes += std::string(axes.empty() ? ", periodic " : ", ") + "xyz"[a];
    return axes;
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

void printText(const nlohmann::ordered_json& j) {
    if (j["kind"] == "surface") {
        const auto& m = j["surface"];
        std::cout << "surface    " << m["vertices"] << " vertices, " << m["edges"] << " edges, "
                  << m["triangles"] << " triangles\n"
                  << "dofs       " << j["dofs"]["edges"] << " edge fluxes, "
                  << j["dofs"]["triangles"] << " triangles\n";
    } else {
        std::cout << "grid       " << j["dim"] << "D " << j["resolution"].dump()
                  << periodicAxes(j["periodic"]) << ", " << j["boundary"].get<std::string>() << ", "
                  << j["wall"].get<std::string>() << "\n"
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
    auto checked = [](const nlohmann::ordered_json& basis) {
        return basis["checked_modes"] == basis["count"]
                   ? std::string()
                   : " (over " + basis["checked_modes"].dump() + " sampled modes)";
    };
    std::cout << "velocity   " << v["count"] << " modes (" << v["harmonic"] << " harmonic), "
              << v["source"].get<std::string>() << ", κ² = " << list(v["eigenvalues"]) << "\n"
              << "           max divergence " << v["max_divergence"].get<double>()
              << ", orthonormality error " << v["orthonormality_error"].get<double>() << checked(v)
              << "\n";
    const auto& s = j["scalar"];
    std::cout << "scalar     " << s["count"] << " " << s["boundary"].get<std::string>()
              << " modes, " << s["source"].get<std::string>() << ", μ² = " << list(s["eigenvalues"])
              << "\n";
    const auto& co = j["coefficients"];
    if (co["storage"] == "none")
        std::cout << "C          none stored (tensor-free), quadrature of "
                  << co["quadrature_elements"] << " vorticity elements\n";
    else
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
    sub->add_option("CACHE_OR_SCENE", opts->target,
                    "a cache file or a scene file (told apart by their contents)")
        ->required();
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder used for a scene");
    sub->add_flag("--json", opts->json, "print one JSON object (keys in tools/README.md)");
    return [sub, opts]() {
        if (!*sub) return -1;
        std::filesystem::path path = opts->target;
        if (!isCache(path)) {
            const SceneSpec scene = loadScene(path);
            Progress progress = Progress::toStderr();
            path = ensureCache(scene, resolveCacheDir(opts->cacheDir), false, progress).path;
        }
        const nlohmann::ordered_json j = summarize(readCache(path), path);
        if (opts->json)
            std::cout << j.dump() << std::endl;
        else
            printText(j);
        return 0;
    };
}

}  // namespace modeflow::cli
