#pragma once
/// @file PythonProgress.h
/// Long calls of the module run with the GIL released; this brings Python back at their
/// progress points: the stage lines of a precompute go to the user's `progress` callable, and a
/// pending Ctrl-C (SIGINT) stops the work there, as KeyboardInterrupt.

#include <ostream>
#include <streambuf>
#include <string>

#include <pybind11/pybind11.h>

#include "engine/core/Progress.h"

namespace modeflow::python {

/// Raises the pending Python exception (KeyboardInterrupt after Ctrl-C) as
/// pybind11::error_already_set, taking the GIL for the check.
void throwIfInterrupted();

/// A Progress whose lines (one per finished stage, and notes) are handed to `callback(line)`
/// (None: dropped), and whose every report, counters included, checks for Ctrl-C.
class PythonProgress {
public:
    explicit PythonProgress(pybind11::object callback);
    PythonProgress(const PythonProgress&) = delete;
    PythonProgress& operator=(const PythonProgress&) = delete;

    Progress& progress() { return mProgress; }

private:
    class Lines : public std::streambuf {
    public:
        explicit Lines(pybind11::object callback) : mCallback(std::move(callback)) {}

    protected:
        int_type overflow(int_type c) override;

    private:
        pybind11::object mCallback;
        std::string mLine;
    };

    Lines mLines;
    std::ostream mStream;
    Progress mProgress;
};

}  // namespace modeflow::python
