#include <chrono>
#include <iostream>
#include <set>
#include <sstream>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"
#include "engine/core/WritableDirectory.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/modeflow/Commands.h"
#include "tools/validate/MantaflowPlume.h"
#include "tools/validate/Report.h"
#include "tools/validate/Study.h"

namespace modeflow::cli {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string fixed(double value, int digits) {
    std::ostringstream out;
    out.precision(digits);
    out << std::fixed << value;
    return out.str();
}

/// The studies `--only` names (comma-separated keys, spaces around them ignored), in their own
/// order; all without it. @throw Error for an empty list, an empty or unknown key, naming the keys
/// there are.
std::vector<validate::Study> chosenStudies(const std::optional<std::string>& only) {
    const std::vector<validate::Study>& all = validate::allStudies();
    if (!only) return all;
    std::string keys;
    for (const validate::Study& s : all) keys += (keys.empty() ? "" : ", ") + s.key;
    std::set<std::string> wanted;
    std::stringstream list(*only + ",");  // so that a trailing comma leaves an empty key too
    for (std::string key; std::getline(list, key, ',');) {
        const std::size_t first = key.find_first_not_of(" \t"), last = key.find_last_not_of(" \t");
        key = first == std::string::npos ? "" : key.substr(first, last - first + 1);
        if (key.empty())
            throw Error("--only \"" + *only + "\": an empty study name (studies: " + keys + ")");
        bool known = false;
        for (const validate::Study& s : all) known = known || s.key == key;
        if (!known) throw Error("--only: no study named \"" + key + "\" (studies: " + keys + ")");
        wanted.insert(key);
    }
    std::vector<validate::Study> chosen;
    for (const validate::Study& s : all)
        if (wanted.count(s.key)) chosen.push_back(s);
    return chosen;
}

}  // namespace

Command addValidate(CLI::App& app) {
    struct Options {
        std::string out;
        bool quick = false;
        std::optional<std::string> only;
        std::optional<std::string> cacheDir;
        std::optional<std::string> blender;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "validate",
        "Reproduce the seed's results: run the validation studies and write DIR/results.json and "
        "DIR/report.html with figures");
    sub->add_option("--out", opts->out, "folder for results.json, report.html and figures/")
        ->required();
    sub->add_flag("--quick", opts->quick,
                  "small grids and short runs (about a minute; what the tests run)");
    sub->add_option("--only", opts->only, "comma-separated studies to run (default: all)");
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder for the studies' bases");
    sub->add_option("--blender", opts->blender,
                    "Blender for the outside check of the 3D plume (default: `blender` on the "
                    "PATH; the full report only)");
    return [sub, opts]() {
        if (!*sub) return -1;
        const std::vector<validate::Study> studies = chosenStudies(opts->only);
        const std::filesystem::path out = opts->out;
        ensureWritableDirectory(out, "--out", "; choose another folder with --out");
        validate::requirePlotting();
        const validate::BlenderChoice blender = validate::findBlender(opts->blender);
        validate::StudyOptions options;
        options.quick = opts->quick;
        options.blender = blender.program;
        options.noBlender = blender.absence;
        if (!opts->quick)
            std::cerr << "validate: outside check (Blender's Mantaflow): "
                      << (blender.program.empty() ? "none, " + blender.absence
                                                  : blender.program.string())
                      << std::endl;
        options.cacheDir = resolveCacheDir(opts->cacheDir);
        options.note = [](const std::string& line) {
            std::cerr << "validate:     " << line << std::endl;
        };

        const auto start = std::chrono::steady_clock::now();
        nlohmann::json results = {{"modeflow_version", MODEFLOW_VERSION}, {"quick", opts->quick}};
        results["studies"] = nlohmann::json::object();
        std::vector<std::string> unmet;
        for (std::size_t i = 0; i < studies.size(); ++i) {
            const validate::Study& study = studies[i];
            std::cerr << "validate: [" << i + 1 << "/" << studies.size() << "] " << study.key
                      << ": " << study.title << std::endl;
            const auto begun = std::chrono::steady_clock::now();
            const validate::StudyResult result = study.run(options);
            const double seconds = secondsSince(begun);
            const validate::Headline& h = result.headline;
            results["studies"][study.key] = {{"title", study.title},
                                             {"seconds", seconds},
                                             {"headline",
                                              {{"name", h.name},
                                               {"value", h.value},
                                               {"expectation", h.expectation},
                                               {"met", h.met}}},
                                             {"data", result.data}};
            results["seconds"] = secondsSince(start);
            writeFileAtomically(out / "results.json", results.dump(1), "validation results");
            std::cerr << "validate: " << study.key << " done in " << fixed(seconds, 1)
                      << " s: " << h.name << " = " << h.value << " (expected " << h.expectation
                      << ": " << (h.met ? "met" : "NOT met") << ")" << std::endl;
            if (!h.met) unmet.push_back(study.key);
        }
        validate::drawReport(out);
        std::cerr << "validate: " << fixed(secondsSince(start), 1) << " s in all" << std::endl;
        std::cout << (out / "report.html").string() << std::endl;
        if (!unmet.empty()) {
            std::string list;
            for (const std::string& key : unmet) list += (list.empty() ? "" : ", ") + key;
            throw Error("validate: the headline expectation of " + list + " was not met (see " +
                        (out / "report.html").string() + ")");
        }
        return 0;
    };
}

}  // namespace modeflow::cli
