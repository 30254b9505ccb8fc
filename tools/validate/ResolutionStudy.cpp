/// @file ResolutionStudy.cpp
/// `resolution` (seed Fig. 6.11): the default scene (smoke rising in the unit disk, 40 modes) on
/// grids of 40², 80² and 160² cells, run on the CPU reference: the smoke's centroid path and the
/// modal energy over time, their distance from the finest grid's, and the smoke at a few times
/// on a common 80² picture for overlaying.

#include <cmath>
#include <string>
#include <vector>

#include "engine/dynamics/Diagnostics.h"
#include "engine/run/Backend.h"
#include "tools/validate/Studies.h"
#include "tools/validate/StudyRuns.h"

namespace modeflow::validate {

extern const char kDefaultScene[];

namespace {

constexpr int kPictureCells = 80;

struct ResolutionRun {
    int cells = 0;
    std::vector<double> time, x, y, energy;
    nlohmann::json pictures = nlohmann::json::array();
};

/// The density averaged onto kPictureCells² blocks (the smoke grid is a multiple of it).
nlohmann::json commonPicture(const MacGrid& grid, const std::vector<double>& density) {
    const int block = grid.cells[0] / kPictureCells;
    nlohmann::json rows = nlohmann::json::array();
    for (int y = 0; y < kPictureCells; ++y) {
        std::vector<double> row;
        for (int x = 0; x < kPictureCells; ++x) {
            double sum = 0.0;
            for (int j = 0; j < block; ++j)
                for (int i = 0; i < block; ++i)
                    sum += density[std::size_t(grid.cellIndex(x * block + i, y * block + j, 0))];
            row.push_back(std::round(sum / (block * block) * 1000.0) / 1000.0);
        }
        rows.push_back(row);
    }
    return rows;
}

ResolutionRun runAt(int cells, int frames, const StudyOptions& options) {
    SceneSpec scene = sceneFromText(kDefaultScene, "default");
    scene.grid.resolution = {cells, cells, 1};
    scene.basis.scalarModes = 0;
    scene.output.frames = frames;
    // Smoke on a grid of 2 × 80² cells whatever the basis grid: only the flow's resolution changes.
    scene.smoke.resolutionScale = 2 * kPictureCells / cells;
    const RunInputs run = prepareStudyRun(scene, options);
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    const std::unique_ptr<Simulator> simulation = backend.makeSimulator(run);
    const MacGrid& grid = simulation->smokeGrid();
    ResolutionRun result;
    result.cells = cells;
    for (int frame = 1; frame <= frames; ++frame) {
        simulation->advanceFrame();
        const std::vector<double> density = simulation->smoke().density;
        double mass = 0.0, mx = 0.0, my = 0.0;
        for (int y = 0; y < grid.cells[1]; ++y)
            for (int x = 0; x < grid.cells[0]; ++x) {
                const double d = density[std::size_t(grid.cellIndex(x, y, 0))];
                mass += d, mx += d * grid.cellCentre(0, x), my += d * grid.cellCentre(1, y);
            }
        result.time.push_back(simulation->time());
        result.x.push_back(mx / mass);
        result.y.push_back(my / mass);
        result.energy.push_back(energy(simulation->velocity()));
        if (frame % (frames / 3) == 0)
            result.pictures.push_back(
                {{"time", simulation->time()}, {"density", commonPicture(grid, density)}});
    }
    return result;
}

}  // namespace

StudyResult resolutionStudy(const StudyOptions& options) {
    const std::vector<int> grids =
        options.quick ? std::vector<int>{40, 80} : std::vector<int>{40, 80, 160};
    const int frames = options.quick ? 60 : 120;
    std::vector<ResolutionRun> runs;
    for (const int cells : grids) {
        options.note(std::to_string(cells) + "²");
        runs.push_back(runAt(cells, frames, options));
    }
    const ResolutionRun& finest = runs.back();
    StudyResult result;
    result.data["scene"] = {{"name", "default"},
                            {"modes", 40},
                            {"smoke_cells", 2 * kPictureCells},
                            {"extent", {-1.1, 1.1, -1.1, 1.1}}};
    result.data["runs"] = nlohmann::json::array();
    double headline = 0.0;
    for (const ResolutionRun& run : runs) {
        double distance = 0.0, energyDifference = 0.0;
        for (std::size_t f = 0; f < run.time.size(); ++f) {
            distance =
                std::max(distance, std::hypot(run.x[f] - finest.x[f], run.y[f] - finest.y[f]));
            energyDifference =
                std::max(energyDifference,
                         std::abs(run.energy[f] - finest.energy[f]) / finest.energy.back());
        }
        result.data["runs"].push_back({{"resolution", run.cells},
                                       {"time", run.time},
                                       {"centroid_x", run.x},
                                       {"centroid_y", run.y},
                                       {"modal_energy", run.energy},
                                       {"max_centroid_distance_to_finest", distance},
                                       {"max_energy_difference_to_finest", energyDifference},
                                       {"pictures", run.pictures}});
        if (&run == &runs[runs.size() - 2]) headline = distance;
    }
    const std::string pair =
        std::to_string(grids[grids.size() - 2]) + "² and " + std::to_string(grids.back()) + "²";
    result.headline = {
        "largest distance between the smoke centroids of " + pair + " (disk radius 1)", headline,
        "below 0.05", headline < 0.05};
    return result;
}

}  // namespace modeflow::validate
