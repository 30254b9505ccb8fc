/// @file WakeStudy.cpp
/// `wake`: vortex shedding behind a cylinder in a wind, a physical check of `[wind]` with a solid
/// standing in it. A closed-form 2D box [0, 8] × [0, 4] (128 × 64 cells) with a wind U = 1 along x
/// and a still ball obstacle of diameter D = 0.5 at (2, 2) (blockage D/H = 1/8); ν = U D / Re and a
/// faint random disturbance at the start to break the symmetry. The transverse velocity at a
/// probe two diameters behind the cylinder's centre oscillates as the wake sheds; St = f D / U,
/// f from the mean period of its upward zero crossings (interpolated between steps) over the
/// run's second half (the shedding grows from the disturbance and settles by then), against
/// Roshko's fit St = 0.212 (1 − 21.2 / Re) at Re = 100 and 150, for bases of more and more modes.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/MacSampling.h"
#include "engine/run/Backend.h"
#include "engine/simulation/WindTransport.h"
#include "tools/validate/Studies.h"
#include "tools/validate/StudyRuns.h"

namespace modeflow::validate {
namespace {

constexpr double kWind = 1.0;
constexpr double kDiameter = 0.5;
constexpr double kStep = 0.02;
constexpr double kCentre[2] = {2.0, 2.0};

double roshko(double re) {
    return 0.212 * (1.0 - 21.2 / re);
}

std::string wakeScene(int modes, double re) {
    return "[grid]\nresolution = [128, 64]\nbounds_min = [0.0, 0.0]\nbounds_max = [8.0, 4.0]\n"
           "[basis]\nvelocity_modes = " +
           std::to_string(modes) +
           "\nscalar_modes = 0\n"
           "[simulation]\ndt = " +
           std::to_string(kStep) +
           "\nintegrator = \"midpoint\"\nviscosity = " + std::to_string(kWind * kDiameter / re) +
           "\n[initial]\nvelocity = \"random\"\nenergy = 0.0001\nseed = 2\n"
           "[wind]\nvelocity = [" +
           std::to_string(kWind) +
           ", 0.0]\n"
           "[[obstacle]]\nshape = \"ball\"\nradius = " +
           std::to_string(kDiameter / 2) + "\npath = [[0.0, " + std::to_string(kCentre[0]) + ", " +
           std::to_string(kCentre[1]) + "]]\n";
}

struct Shedding {
    std::vector<double> time, probe;  ///< the probe's transverse velocity, every step
    double strouhal = 0.0;
    int periods = 0;
};

/// f D / U from the upward zero crossings of the probe's signal (its mean removed) after `from`.
Shedding shedding(const SceneSpec& scene, double duration, double from,
                  const StudyOptions& options) {
    const RunInputs run = prepareStudyRun(scene, options);
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    const std::unique_ptr<Simulator> simulation = backend.makeSimulator(run);
    const MacGrid grid = airGridOf(run.cache.grid, run.settings.wind);
    const Vec3 probe{kCentre[0] + 2.0 * kDiameter, kCentre[1], 0.5};
    Shedding s;
    const int steps = int(std::lround(duration / kStep));
    for (int n = 1; n <= steps; ++n) {
        simulation->advanceSteps(1);
        const std::vector<double> faces = simulation->faceVelocity();
        s.time.push_back(n * kStep);
        s.probe.push_back(sampleVelocity(grid, std::span<const double>(faces), probe)[1]);
    }
    const auto first = std::size_t(std::lround(from / kStep));
    double mean = 0.0;
    for (std::size_t i = first; i < s.probe.size(); ++i) mean += s.probe[i];
    mean /= double(s.probe.size() - first);
    std::vector<double> crossings;
    for (std::size_t i = first; i + 1 < s.probe.size(); ++i) {
        const double a = s.probe[i] - mean, b = s.probe[i + 1] - mean;
        if (a < 0.0 && b >= 0.0) crossings.push_back(s.time[i] + kStep * a / (a - b));
    }
    s.periods = int(crossings.size()) - 1;
    if (s.periods >= 1)
        s.strouhal = s.periods / (crossings.back() - crossings.front()) * kDiameter / kWind;
    return s;
}

}  // namespace

StudyResult wakeStudy(const StudyOptions& options) {
    const std::vector<int> modeCounts =
        options.quick ? std::vector<int>{200, 400} : std::vector<int>{200, 400, 800};
    const double duration = options.quick ? 60.0 : 80.0, from = duration / 2.0;
    StudyResult result;
    result.data["scene"] = {{"box", "[0, 8] × [0, 4], closed-form modes"},
                            {"resolution", {128, 64}},
                            {"wind", kWind},
                            {"diameter", kDiameter},
                            {"centre", {kCentre[0], kCentre[1]}},
                            {"probe", {kCentre[0] + 2.0 * kDiameter, kCentre[1]}},
                            {"dt", kStep},
                            {"duration", duration},
                            {"measured_from", from}};
    double worst = 0.0;
    for (const double re : {100.0, 150.0}) {
        nlohmann::json runs = nlohmann::json::array();
        for (const int modes : modeCounts) {
            options.note("Re " + std::to_string(int(re)) + ", " + std::to_string(modes) + " modes");
            const Shedding s =
                shedding(sceneFromText(wakeScene(modes, re), "wake"), duration, from, options);
            runs.push_back({{"modes", modes},
                            {"strouhal", s.strouhal},
                            {"periods", s.periods},
                            {"time", thinned(s.time, 5)},
                            {"probe", thinned(s.probe, 5)}});
            if (modes == modeCounts.back())
                worst = std::max(worst, std::abs(s.strouhal / roshko(re) - 1.0));
        }
        result.data["re_" + std::to_string(int(re))] = {
            {"re", re}, {"roshko", roshko(re)}, {"runs", runs}};
    }
    result.headline = {"largest |St / Roshko's St − 1| at Re 100 and 150, " +
                           std::to_string(modeCounts.back()) + " modes",
                       worst, "below 0.2", worst < 0.2};
    return result;
}

}  // namespace modeflow::validate
