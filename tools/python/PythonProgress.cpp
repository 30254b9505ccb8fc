#include "tools/python/PythonProgress.h"

#include <utility>

namespace py = pybind11;

namespace modeflow::python {

void throwIfInterrupted() {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

PythonProgress::PythonProgress(py::object callback)
    : mLines(std::move(callback)), mStream(&mLines), mProgress(&mStream, true) {
    // An exception of the buffer (Ctrl-C, the callable's own) leaves the stream as it is,
    // rather than being swallowed into its badbit.
    mStream.exceptions(std::ios::badbit);
}

PythonProgress::Lines::int_type PythonProgress::Lines::overflow(int_type c) {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    // A live counter rewrites its line with '\r': keep what follows the last one.
    if (ch == '\r') {
        mLine.clear();
        throwIfInterrupted();
    } else if (ch == '\n') {
        std::string line;
        std::swap(line, mLine);
        // The live line's erase sequence (Progress.cpp) is no text.
        for (std::size_t at; (at = line.find("\033[K")) != std::string::npos;) line.erase(at, 3);
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!mCallback.is_none() && !line.empty()) mCallback(line);
    } else {
        mLine.push_back(ch);
    }
    return c;
}

}  // namespace modeflow::python
