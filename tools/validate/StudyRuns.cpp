#include "tools/validate/StudyRuns.h"

#include <cstdio>
#include <cstdlib>

#include "precompute/scene/SceneLoader.h"

namespace modeflow::validate {

SceneSpec sceneFromText(const std::string& text, const std::string& name) {
    return parseScene(text, name + ".toml");
}

RunInputs prepareStudyRun(const SceneSpec& scene, const StudyOptions& options, RunParts parts) {
    Progress quiet = Progress::silent();
    return prepareRun(scene, options.cacheDir, quiet, parts);
}

std::vector<double> thinned(const std::vector<double>& values, std::size_t stride) {
    std::vector<double> kept;
    for (std::size_t i = 0; i < values.size(); i += stride) kept.push_back(values[i]);
    if (!values.empty() && (values.size() - 1) % stride != 0) kept.push_back(values.back());
    return kept;
}

double significant(double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return std::strtod(text, nullptr);
}

std::string scientific(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1e", value);
    return text;
}

std::vector<double> toStd(const Eigen::VectorXd& v) {
    return {v.data(), v.data() + v.size()};
}

}  // namespace modeflow::validate
