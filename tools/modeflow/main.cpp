/// modeflow — model-reduced fluid simulation. Library errors arrive as modeflow::Error and leave
/// as one line on stderr with exit status 1; usage errors exit with CLI11's status. Under an MPI
/// launcher every rank runs this: only `precompute` shares work among ranks, and rank 0 alone
/// speaks for refusals and usage errors, which every rank meets alike (out of memory and internal
/// errors, which may be one rank's own, are said by that rank, with its number).

#include <iostream>
#include <new>
#include <string>

#include "engine/core/Error.h"
#include "engine/core/LaunchedRank.h"
#include "tools/modeflow/Commands.h"

int main(int argc, char** argv) {
    CLI::App app(
        "modeflow " MODEFLOW_VERSION
        ": model-reduced fluid simulation (precompute spectral bases, inspect caches, run the "
        "reduced dynamics, simulate scenes to OpenVDB frames, stir them in a window, reproduce the "
        "seed's results)");
    app.set_version_flag("--version", std::string(MODEFLOW_VERSION));
    app.require_subcommand(1);
    const modeflow::cli::Command commands[] = {
        modeflow::cli::addPrecompute(app), modeflow::cli::addInspect(app),
        modeflow::cli::addModes(app),      modeflow::cli::addRun(app),
        modeflow::cli::addStir(app),       modeflow::cli::addValidate(app)};
    const modeflow::LaunchedRank place = modeflow::launchedRank();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return place.primary() ? app.exit(e) : e.get_exit_code();
    }
    const std::string name = app.get_subcommands().front()->get_name();
    // "modeflow: error (rank 2): " where several ranks may speak.
    const std::string rank = place.size > 1 ? " (rank " + std::to_string(place.rank) + ")" : "";
    try {
        if (place.size > 1 && name != "precompute")
            throw modeflow::Error("modeflow " + name +
                                  " runs as one process; only `modeflow precompute` shares its "
                                  "work among MPI ranks: start it without mpirun (" +
                                  std::to_string(place.size) + " ranks here)");
        for (const auto& command : commands)
            if (const int status = command(); status >= 0) return status;
    } catch (const modeflow::Error& e) {
        if (place.primary()) std::cerr << "modeflow: error: " << e.what() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        // The precompute and run name their stage; an allocation failing elsewhere names the
        // command.
        std::cerr << "modeflow: error" << rank << ": out of memory in modeflow " << name << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "modeflow: internal error" << rank << ": " << e.what() << "\n";
        return 2;
    }
    return 0;
}
