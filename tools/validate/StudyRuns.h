#pragma once
/// @file StudyRuns.h
/// What the studies share to set up their runs: scenes written as TOML text (checked by the scene
/// loader like any scene file) and runs prepared on the cache folder of `modeflow validate`.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "tools/compose/RunPreparation.h"
#include "tools/validate/Study.h"

namespace modeflow::validate {

/// The scene in `text`, named `name` (its messages say "name.toml: ...").
SceneSpec sceneFromText(const std::string& text, const std::string& name);

/// prepareRun on options.cacheDir, quietly.
RunInputs prepareStudyRun(const SceneSpec& scene, const StudyOptions& options,
                          RunParts parts = RunParts::DynamicsAndSmoke);

/// Every `stride`-th value of a series and its last one: figures need a few hundred points.
std::vector<double> thinned(const std::vector<double>& values, std::size_t stride);

/// `value` rounded to `digits` significant digits: for pictures, whose colours need no more and
/// whose numbers are most of results.json.
double significant(double value, int digits);

/// `value` in scientific notation with 2 significant digits ("3.1e-15").
std::string scientific(double value);

/// A vector's values as a std::vector (for JSON).
std::vector<double> toStd(const Eigen::VectorXd& v);

}  // namespace modeflow::validate
