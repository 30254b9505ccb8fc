/// @file ReducedVsFullStudy.cpp
/// `reduced_vs_full` (seed Figs. 6.12, 6.16): reduced runs of N modes against the full run of the
/// same grid, whose basis is every divergence-free mode the grid has (so the full run is the
/// grid's own Galerkin dynamics, the same discretization without truncation). Today's experiment
/// is a bounded plume: a hot disk at the floor of a closed box. Each run's smoke centroid height
/// and peak speed over time show the rise converging as N grows, with the relative L2 and L∞
/// velocity errors against the full run. The reduced runs keep the full basis's leading modes,
/// so all runs share one eigensolve.

#include <cmath>
#include <string>
#include <vector>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/pipeline/Backend.h"
#include "engine/stir/ShapedBases.h"
#include "tools/validate/Studies.h"
#include "tools/validate/StudyRuns.h"

namespace modeflow::validate {
namespace {

std::string plumeScene(int cells, int modes) {
    const std::string n = std::to_string(cells);
    return "[grid]\nresolution = [" + n + ", " + n +
           "]\nbounds_min = [0.0, 0.0]\nbounds_max = [1.0, 1.0]\n" +
           "[basis]\nvelocity_modes = " + std::to_string(modes) + "\nscalar_modes = 0\n" +
           "[simulation]\ndt = 0.02\nintegrator = \"midpoint\"\n"
           "[[source]]\nshape = \"ball\"\ncenter = [0.5, 0.15]\nradius = 0.1\ndensity = "
           "1.0\ntemperature = 1.0\n"
           "[smoke]\nbuoyancy = 1.0\nresolution_scale = 2\n"
           "[output]\nframes = 1\nsteps_per_frame = 1\n";
}

/// The run of the leading `modes` modes of `full`: its basis, its Galerkin coefficients (sparse
/// where the full ones are), the same settings and smoke mask, from rest.
RunInputs leadingRun(const RunInputs& full, int modes) {
    RunInputs run;
    run.scene = full.scene;
    run.cache = stir::leadingModes(full.cache, modes);
    run.coefficients = stir::leadingCoefficients(*full.coefficients, modes);
    if (dynamic_cast<const SparseCoefficients*>(full.coefficients.get()))
        run.coefficients = std::make_unique<SparseCoefficients>(SparseCoefficients::fromDense(
            static_cast<const DenseCoefficients&>(*run.coefficients)));
    run.settings = SimulationSettings::fromScene(full.scene, run.cache);
    run.smokeMask = full.smokeMask;
    run.initialVelocity = Eigen::VectorXd::Zero(modes);
    return run;
}

double centroidHeight(const Simulator& simulation) {
    const MacGrid& grid = simulation.smokeGrid();
    const std::vector<double> density = simulation.smoke().density;
    double mass = 0.0, moment = 0.0;
    for (int y = 0; y < grid.cells[1]; ++y)
        for (int x = 0; x < grid.cells[0]; ++x) {
            const double d = density[std::size_t(grid.cellIndex(x, y, 0))];
            mass += d, moment += d * grid.cellCentre(1, y);
        }
    return moment / mass;
}

double maxAbs(const std::vector<double>& values) {
    double m = 0.0;
    for (const double v : values) m = std::max(m, std::abs(v));
    return m;
}

struct PlumeRun {
    int modes = 0;
    std::unique_ptr<RunInputs> inputs;
    std::unique_ptr<Simulator> simulation;
    std::vector<double> height, peakSpeed, l2, linf;
};

}  // namespace

StudyResult reducedVsFullStudy(const StudyOptions& options) {
    const int cells = options.quick ? 16 : 24;
    const std::vector<int> counts =
        options.quick ? std::vector<int>{10, 25, 50, 100} : std::vector<int>{25, 50, 100, 200, 400};
    const int frames = options.quick ? 80 : 200;
    // Every divergence-free mode of the closed box: faces − cells + 1.
    const int all = 2 * cells * (cells - 1) - cells * cells + 1;
    options.note("full: all " + std::to_string(all) + " modes of the " + std::to_string(cells) +
                 "² box");
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    std::vector<PlumeRun> runs(counts.size() + 1);
    runs.back().inputs = std::make_unique<RunInputs>(
        prepareStudyRun(sceneFromText(plumeScene(cells, all), "reduced_vs_full_plume"), options));
    runs.back().modes = all;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        runs[r].modes = counts[r];
        runs[r].inputs = std::make_unique<RunInputs>(leadingRun(*runs.back().inputs, counts[r]));
    }
    for (PlumeRun& run : runs) run.simulation = backend.makeSimulator(*run.inputs);

    std::vector<double> time;
    for (int frame = 1; frame <= frames; ++frame) {
        for (PlumeRun& run : runs) run.simulation->advanceSteps(1);
        const Eigen::VectorXd vFull = runs.back().simulation->velocity();
        if (vFull.norm() == 0.0)
            continue;  // the first step: the source has not heated anything yet
        time.push_back(runs.back().simulation->time());
        const std::vector<double> uFull = runs.back().simulation->faceVelocity();
        for (PlumeRun& run : runs) {
            const std::vector<double> u = run.simulation->faceVelocity();
            run.height.push_back(centroidHeight(*run.simulation));
            run.peakSpeed.push_back(maxAbs(u));
            Eigen::VectorXd difference = -vFull;
            difference.head(run.modes) += run.simulation->velocity();
            run.l2.push_back(difference.norm() / vFull.norm());
            double worst = 0.0;
            for (std::size_t f = 0; f < u.size(); ++f)
                worst = std::max(worst, std::abs(u[f] - uFull[f]));
            run.linf.push_back(worst / maxAbs(uFull));
        }
        if (frame % 40 == 0) options.note("t = " + std::to_string(time.back()));
    }

    StudyResult result;
    result.data["plume"] = {{"domain", "closed unit box"},
                            {"resolution", cells},
                            {"full_modes", all},
                            {"source", "hot disk r = 0.1 at (0.5, 0.15), buoyancy 1"},
                            {"dt", 0.02},
                            {"time", time},
                            {"runs", nlohmann::json::array()}};
    const double fullRise = runs.back().height.back() - runs.back().height.front();
    std::vector<double> finalErrors;
    for (const PlumeRun& run : runs) {
        const double rise = run.height.back() - run.height.front();
        result.data["plume"]["runs"].push_back({{"modes", run.modes},
                                                {"centroid_height", run.height},
                                                {"peak_speed", run.peakSpeed},
                                                {"relative_l2", run.l2},
                                                {"relative_linf", run.linf},
                                                {"rise_fraction_of_full", rise / fullRise}});
        if (run.modes != all) finalErrors.push_back(run.l2.back());
    }
    const double ratio = finalErrors.back() / finalErrors.front();
    result.headline = {"final L2 error against the full run, " + std::to_string(counts.back()) +
                           " modes / " + std::to_string(counts.front()) + " modes",
                       ratio, "below 1 (the error falls with more modes)", ratio < 1.0};
    return result;
}

}  // namespace modeflow::validate
