#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tools/compose/CacheDirectory.h"
#include "tools/compose/CacheSummary.h"
#include "tools/modeflow/Commands.h"

namespace modeflow::cli {
namespace {

/// ", periodic x, z" for the periodic axes; nothing when every axis has walls.
std::string periodicAxes(const nlohmann::ordered_json& flags) {
    std::string axes;
    for (std::size_t a = 0; a < flags.size(); ++a)
        if (flags[a].get<bool>())
            axes += std::string(axes.empty() ? ", periodic " : ", ") + "xyz"[a];
    return axes;
}

/// ", open y_max" for the open sides; nothing when there are none.
std::string openSides(const nlohmann::ordered_json& sides) {
    std::string text;
    for (const auto& side : sides)
        text += (text.empty() ? ", open " : ", ") + side.get<std::string>();
    return text;
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
                  << periodicAxes(j["periodic"]) << openSides(j["open"]) << ", "
                  << j["boundary"].get<std::string>() << ", " << j["wall"].get<std::string>()
                  << "\n"
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
        Progress progress = Progress::toStderr();
        const nlohmann::ordered_json j =
            cacheSummary(inspectedCache(opts->target, resolveCacheDir(opts->cacheDir), progress));
        if (opts->json)
            std::cout << j.dump() << std::endl;
        else
            printText(j);
        return 0;
    };
}

}  // namespace modeflow::cli
