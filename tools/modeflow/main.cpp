/// modeflow — model-reduced fluid simulation. Library errors arrive as modeflow::Error and leave
/// as one line on stderr with exit status 1; usage errors exit with CLI11's status.

#include <iostream>
#include <new>

#include "engine/core/Error.h"
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
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        for (const auto& command : commands)
            if (const int status = command(); status >= 0) return status;
    } catch (const modeflow::Error& e) {
        std::cerr << "modeflow: error: " << e.what() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        // The precompute and run name their stage; an allocation failing elsewhere names the
        // command.
        std::cerr << "modeflow: error: out of memory in modeflow "
                  << app.get_subcommands().front()->get_name() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "modeflow: internal error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
