/// @file ReducedVsFullStudy.cpp
/// `reduced_vs_full` (seed Figs. 6.12, 6.16): reduced runs of N modes against the full grid.
///
/// - `plume`: a hot disk at the floor of a closed 2D box, against the full run of the same grid,
///   whose basis is every divergence-free mode the grid has (the grid's own Galerkin dynamics,
///   the same discretization without truncation): each run's smoke centroid height and peak
///   speed over time, and the relative L2 and L∞ velocity errors against the full run. The
///   reduced runs keep the full basis's leading modes, so all share one basis.
/// - `plume_3d`: the hot ball of a closed 64³ box (r = 0.08 at the floor, buoyancy 1, the job of
///   tools/validate/README.md "The slow plume") with closed-form bases of 50 … 2000 modes: the
///   first step's response to the ball's buoyancy, dt·P_N(g), against the full grid's dt·P(g)
///   (a pressure solve, PressureProjection.h), and each run's rise over time; in the full report,
///   with Blender found, Blender's Mantaflow on the same scene as the outside reference
///   (MantaflowPlume.h).
/// - `periodic`: the seed's band-limited flow on a torus against a full-spectrum run
///   (PeriodicReducedVsFull.cpp); its final errors are the study's headline.

#include <cmath>
#include <string>
#include <vector>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/ShapedBases.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/reference/ForceField.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/run/Backend.h"
#include "tools/validate/MantaflowPlume.h"
#include "tools/validate/PressureProjection.h"
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
    run.cache = leadingModes(full.cache, modes);
    run.coefficients = leadingCoefficients(*full.coefficients, modes);
    if (dynamic_cast<const SparseCoefficients*>(full.coefficients.get()))
        run.coefficients = std::make_unique<SparseCoefficients>(SparseCoefficients::fromDense(
            static_cast<const DenseCoefficients&>(*run.coefficients)));
    run.settings = SimulationSettings::fromScene(full.scene, run.cache);
    run.smokeMask = full.smokeMask;
    run.initialVelocity = Eigen::VectorXd::Zero(modes);
    return run;
}

/// The smoke density's centroid height in 3D (z).
double centroidHeight3d(const Simulator& simulation) {
    const MacGrid& grid = simulation.smokeGrid();
    const std::vector<double> density = simulation.smoke().density;
    double mass = 0.0, moment = 0.0;
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double d = density[std::size_t(grid.cellIndex(x, y, z))];
                mass += d, moment += d * grid.cellCentre(2, z);
            }
    return moment / mass;
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

std::string ballScene(int cells, int modes, int frames) {
    const std::string n = std::to_string(cells);
    return "[grid]\nresolution = [" + n + ", " + n + ", " + n +
           "]\nbounds_min = [0.0, 0.0, 0.0]\nbounds_max = [1.0, 1.0, 1.0]\n[basis]\nvelocity_modes "
           "= " +
           std::to_string(modes) +
           "\nscalar_modes = 0\n[simulation]\ndt = 0.02\nintegrator = \"midpoint\"\n"
           "[[source]]\nshape = \"ball\"\ncenter = [0.5, 0.5, 0.1]\nradius = 0.08\ndensity = 1.0\n"
           "temperature = 1.0\n[smoke]\nbuoyancy = 1.0\n[output]\nframes = " +
           std::to_string(frames) + "\nsteps_per_frame = 1\n";
}

/// 1 in the smoke cells whose centre is inside the source ball, 0 elsewhere.
std::vector<double> ballTemperature(const MacGrid& grid) {
    std::vector<double> t(std::size_t(grid.cellCount()), 0.0);
    for (int z = 0; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double dx = grid.cellCentre(0, x) - 0.5, dy = grid.cellCentre(1, y) - 0.5,
                             dz = grid.cellCentre(2, z) - 0.1;
                if (dx * dx + dy * dy + dz * dz <= 0.08 * 0.08)
                    t[std::size_t(grid.cellIndex(x, y, z))] = 1.0;
            }
    return t;
}

/// The peak upward speed and the mean upward speed weighted by the temperature of the two cells
/// each up face separates (the ball's rise), of a face field.
std::pair<double, double> riseOf(const MacGrid& grid, std::span<const double> u,
                                 const std::vector<double>& t) {
    double peak = 0.0, weighted = 0.0, weight = 0.0;
    for (int z = 1; z < grid.cells[2]; ++z)
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double w = 0.5 * (t[std::size_t(grid.cellIndex(x, y, z))] +
                                        t[std::size_t(grid.cellIndex(x, y, z - 1))]);
                const double uz = u[std::size_t(grid.faceIndex(2, x, y, z))];
                peak = std::max(peak, uz);
                weighted += w * uz, weight += w;
            }
    return {peak, weighted / weight};
}

/// Blender's Mantaflow on the 3D experiment's scene: its series, or `not_run` saying why.
nlohmann::json mantaflowReference(const StudyOptions& options, int cells, int frames) {
    if (options.quick)
        return {{"not_run", "--quick runs no outside check (the full report does, with Blender)"}};
    if (options.blender.empty()) return {{"not_run", options.noBlender}};
    options.note("3D plume: Blender's Mantaflow, " + std::to_string(cells) + "³, " +
                 std::to_string(frames) + " frames (" + options.blender.string() + ")");
    try {
        const nlohmann::json run = runMantaflowPlume(options.blender, cells, frames);
        nlohmann::json series = {{"solver", run.at("solver")},
                                 {"resolution", run.at("resolution")},
                                 {"scene", run.at("scene")}};
        for (const char* key : {"time", "centroid_height", "peak_speed", "smoke_mass"}) {
            std::vector<double> values;
            for (const nlohmann::json& frame : run.at("frames")) values.push_back(frame.at(key));
            series[key] = values;
        }
        return series;
    } catch (const std::exception& e) {
        // Recorded, and drawn in the report, rather than losing the study's other runs.
        options.note(std::string("Mantaflow failed: ") + e.what());
        return {{"not_run", std::string("Blender's run failed: ") + e.what()}};
    }
}

/// The 3D experiment (see the file's comment).
nlohmann::json ballPlume(const StudyOptions& options) {
    const int cells = options.quick ? 24 : 64, frames = options.quick ? 15 : 60;
    const std::vector<int> counts = options.quick ? std::vector<int>{50, 200, 500}
                                                  : std::vector<int>{50, 100, 200, 500, 1000, 2000};
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    nlohmann::json result = {
        {"resolution", cells},
        {"source", "hot ball r = 0.08 at (0.5, 0.5, 0.1), buoyancy 1, closed unit box"},
        {"dt", 0.02},
        {"runs", nlohmann::json::array()}};
    std::pair<double, double> full{0.0, 0.0};
    for (const int n : counts) {
        options.note("3D plume, " + std::to_string(n) + " modes");
        const RunInputs run = prepareStudyRun(
            sceneFromText(ballScene(cells, n, frames), "reduced_vs_full_ball"), options);
        const MacGrid grid = MacGrid::fromSpec(run.cache.grid);
        const std::vector<double> t = ballTemperature(grid);
        if (n == counts.front()) {
            // The full grid's response: P(g) for the ball's buoyancy g (one value per DOF).
            const Eigen::VectorXd g = reference::forceDensity(run.cache, {1.0, 1, t, {}}, {});
            std::vector<double> field(std::size_t(grid.faceTotal()), 0.0);
            for (std::size_t d = 0; d < run.cache.faces.size(); ++d)
                field[std::size_t(run.cache.faces[d])] = g[Eigen::Index(d)];
            full = riseOf(grid, pressureProjection(grid, field), t);
            result["full_response"] = {{"peak", full.first}, {"mean_rise", full.second}};
        }
        // One explicit step from rest with the ball hot: u = dt·P_N(g).
        const std::unique_ptr<Simulator> response = backend.makeSimulator(run);
        response->setIntegrator(Integrator::Explicit);
        response->restore(0.0, Eigen::VectorXd::Zero(n), SmokeFields{t, t});
        response->advanceSteps(1);
        const std::pair<double, double> reduced = riseOf(grid, response->faceVelocity(), t);
        // The run itself: the source heating from t = 0.
        const std::unique_ptr<Simulator> simulation = backend.makeSimulator(run);
        std::vector<double> time, height, peak;
        for (int frame = 1; frame <= frames; ++frame) {
            simulation->advanceFrame();
            time.push_back(simulation->time());
            height.push_back(centroidHeight3d(*simulation));
            peak.push_back(maxAbs(simulation->faceVelocity()));
        }
        result["runs"].push_back({{"modes", n},
                                  {"response_peak_fraction", reduced.first / 0.02 / full.first},
                                  {"response_rise_fraction", reduced.second / 0.02 / full.second},
                                  {"time", time},
                                  {"centroid_height", height},
                                  {"peak_speed", peak}});
    }
    result["mantaflow"] = mantaflowReference(options, cells, frames);
    return result;
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
    for (const PlumeRun& run : runs) {
        const double rise = run.height.back() - run.height.front();
        result.data["plume"]["runs"].push_back({{"modes", run.modes},
                                                {"centroid_height", run.height},
                                                {"peak_speed", run.peakSpeed},
                                                {"relative_l2", run.l2},
                                                {"relative_linf", run.linf},
                                                {"rise_fraction_of_full", rise / fullRise}});
    }
    result.data["plume_3d"] = ballPlume(options);
    result.data["periodic"] = periodicBandLimited(options);
    const nlohmann::json& periodic = result.data["periodic"]["runs"];
    const double ratio = periodic.back()["relative_l2"].back().get<double>() /
                         periodic.front()["relative_l2"].back().get<double>();
    result.headline = {"periodic band-limited flow: final L2 error against the full spectrum, " +
                           std::to_string(periodic.back()["modes"].get<int>()) + " modes / " +
                           std::to_string(periodic.front()["modes"].get<int>()) + " modes",
                       ratio, "below 1 (the error falls with more modes)", ratio < 1.0};
    return result;
}

}  // namespace modeflow::validate
