#pragma once
/// @file Study.h
/// One study of `modeflow validate` (tools/validate/README.md): a measurement of how far the
/// solver is from a reference, run small (`--quick`) or full, giving its numbers for
/// results.json and one headline figure with the expectation it is held to.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace modeflow::validate {

struct StudyOptions {
    bool quick = false;              ///< small grids and short runs (the test suite's size)
    std::filesystem::path cacheDir;  ///< where the bases are cached (reused across runs)
    std::function<void(const std::string&)> note;  ///< a line of progress within the study
    /// Blender for the outside check of the 3D plume (MantaflowPlume.h); empty: none, and
    /// `noBlender` says why (the report says so).
    std::filesystem::path blender;
    std::string noBlender;
};

/// The number a reader looks at first, and what it should be.
struct Headline {
    std::string name;  ///< what the value is, e.g. "velocity order, disk, cut cells"
    double value = 0.0;
    std::string expectation;  ///< e.g. "≥ 1.8 (second order)"
    bool met = false;
};

struct StudyResult {
    nlohmann::json data;  ///< every figure's numbers, under the keys tools/validate/README.md names
    Headline headline;
};

struct Study {
    std::string key;    ///< its key in results.json ("convergence", "integrators", ...)
    std::string title;  ///< a short sentence for the progress line and the report
    std::function<StudyResult(const StudyOptions&)> run;
};

/// Every study, in the order they run and appear in the report.
const std::vector<Study>& allStudies();

}  // namespace modeflow::validate
