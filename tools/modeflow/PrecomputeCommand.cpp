#include <iostream>

#include "precompute/Precompute.h"
#include "precompute/scene/SceneLoader.h"
#include "precompute/solve/ProcessGroup.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/modeflow/Commands.h"

namespace modeflow::cli {
namespace {

/// "precompute on 4 MPI ranks", and when partitions are fewer than ranks "in 2 partitions
/// (each factorization on 2 ranks)".
std::string rankLine(const ProcessGroup& group) {
    std::string line = "precompute on " + std::to_string(group.size) + " MPI ranks";
    if (group.partitions == group.size) return line;
    const int least = group.size / group.partitions;
    return line + " in " + std::to_string(group.partitions) +
           (group.partitions == 1 ? " partition" : " partitions") + " (each factorization on " +
           (group.size % group.partitions == 0 ? "" : "at least ") + std::to_string(least) +
           " ranks)";
}

}  // namespace

Command addPrecompute(CLI::App& app) {
    struct Options {
        std::string scene;
        std::optional<std::string> cacheDir;
        bool force = false;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "precompute",
        "Compute the scene's eigenbases into a cache file (reused when unchanged); "
        "prints the cache file's path on the last line");
    sub->add_option("SCENE", opts->scene, "scene file (TOML)")->required();
    sub->add_option("--cache-dir", opts->cacheDir,
                    "cache folder (default: $MODEFLOW_CACHE_DIR, else $XDG_CACHE_HOME/modeflow, "
                    "else ~/.cache/modeflow)");
    sub->add_flag("--force", opts->force, "recompute even when a valid cache exists");
    return [sub, opts]() {
        if (!*sub) return -1;
        // `mpirun -n K modeflow precompute`: K ranks share the eigensolves, rank 0 reports and
        // writes the cache.
        const ProcessGroup group = joinProcessGroup();
        const SceneSpec scene = loadScene(opts->scene);
        Progress progress = group.primary() ? Progress::toStderr() : Progress::silent();
        if (group.size > 1) progress.note(rankLine(group));
        const CacheOutcome outcome =
            ensureCache(scene, resolveCacheDir(opts->cacheDir), opts->force, progress);
        if (!group.primary()) return 0;
        if (outcome.reused) std::cerr << "cache is up to date\n";
        std::cout << outcome.path.string() << std::endl;
        return 0;
    };
}

}  // namespace modeflow::cli
