#pragma once
/// @file Report.h
/// The report of `modeflow validate`: report.py (embedded at build time) reads DIR/results.json
/// and draws DIR/figures/*.png with matplotlib and DIR/report.html with the figures inline.

#include <filesystem>
#include <string>

namespace modeflow::validate {

/// The Python that draws the report: $MODEFLOW_PYTHON, else Debian's /usr/bin/python3 (where
/// python3-matplotlib installs), else `python3` on the PATH.
std::string reportInterpreter();

/// Checks, before any study runs, that the interpreter starts and imports matplotlib.
/// @throw modeflow::Error saying what to install (python3-matplotlib) or set (MODEFLOW_PYTHON).
void requirePlotting();

/// Draws the report of DIR/results.json into DIR.
/// @throw modeflow::Error when the script fails (its messages went to stderr).
void drawReport(const std::filesystem::path& dir);

}  // namespace modeflow::validate
