#pragma once
/// @file Commands.h
/// The `modeflow` subcommands (tools/README.md, "Command line"). Each registers its options on the
/// CLI11 app and returns the function that runs it; errors propagate as modeflow::Error to main().

#include <functional>

#include <CLI/CLI.hpp>

namespace modeflow::cli {

using Command = std::function<int()>;

Command addPrecompute(CLI::App& app);
Command addInspect(CLI::App& app);
Command addModes(CLI::App& app);
Command addRun(CLI::App& app);
Command addStir(CLI::App& app);
Command addValidate(CLI::App& app);

}  // namespace modeflow::cli
