/// @file MhdStudy.cpp
/// `mhd` (seed Fig. 6.18): the rotor of scenes/seed/mhd_rotor_2d.toml, a vortex in a uniform
/// magnetic field, on the CPU reference: kinetic, magnetic and total energy over time and the dye
/// at a few times, with the field and without it (magnetic_strength = 0). The rotor's cross
/// helicity Σv_iF_i is 0 by symmetry throughout, so its conservation is shown on
/// scenes/mhd_disk_2d.toml, a random flow in a random field, where it is not.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/dynamics/Diagnostics.h"
#include "engine/run/Backend.h"
#include "tools/validate/Studies.h"
#include "tools/validate/StudyRuns.h"

namespace modeflow::validate {

extern const char kMhdRotorScene[];
extern const char kMhdDiskScene[];

namespace {

/// The smoke density averaged over blocks of `block`² cells, rows bottom to top, 3 decimals.
nlohmann::json densityPicture(const Simulator& simulation, int block) {
    const MacGrid& grid = simulation.smokeGrid();
    const std::vector<double> density = simulation.smoke().density;
    nlohmann::json rows = nlohmann::json::array();
    for (int y = 0; y + block <= grid.cells[1]; y += block) {
        std::vector<double> row;
        for (int x = 0; x + block <= grid.cells[0]; x += block) {
            double sum = 0.0;
            for (int j = 0; j < block; ++j)
                for (int i = 0; i < block; ++i)
                    sum += density[std::size_t(grid.cellIndex(x + i, y + j, 0))];
            row.push_back(std::round(sum / (block * block) * 1000.0) / 1000.0);
        }
        rows.push_back(row);
    }
    return rows;
}

struct MhdRun {
    nlohmann::json data;
    double energyDrift = 0.0, helicityDrift = 0.0;
};

/// The scene on the CPU reference: energies and cross helicity every step, and with `pictures` the
/// dye at four times.
MhdRun runMhd(const SceneSpec& scene, const StudyOptions& options, bool pictures) {
    const RunInputs run = prepareStudyRun(scene, options);
    const Backend backend(BackendChoice{BackendKind::CpuReference, {}});
    const std::unique_ptr<Simulator> simulation = backend.makeSimulator(run);
    const int frames = scene.output.frames;
    const int block = std::max(1, simulation->smokeGrid().cells[0] / 128);
    std::vector<double> time, kinetic, magnetic, helicity;
    nlohmann::json shots = nlohmann::json::array();
    const auto record = [&] {
        const Eigen::VectorXd v = simulation->velocity(), f = simulation->magneticField();
        time.push_back(simulation->time());
        kinetic.push_back(energy(v));
        magnetic.push_back(energy(f));
        helicity.push_back(crossHelicity(v, f));
    };
    record();
    for (int frame = 1; frame <= frames; ++frame) {
        for (int s = 0; s < scene.output.stepsPerFrame; ++s) {
            simulation->advanceSteps(1);
            record();
        }
        if (pictures && frame % (frames / 4) == 0)
            shots.push_back(
                {{"time", simulation->time()}, {"density", densityPicture(*simulation, block)}});
    }
    MhdRun result;
    const double e0 = kinetic[0] + magnetic[0];
    for (std::size_t i = 0; i < time.size(); ++i) {
        result.energyDrift =
            std::max(result.energyDrift, std::abs(kinetic[i] + magnetic[i] - e0) / e0);
        result.helicityDrift = std::max(
            result.helicityDrift, std::abs(helicity[i] - helicity[0]) / std::abs(helicity[0]));
    }
    const Vec3& lo = scene.grid.boundsMin;
    const Vec3& hi = scene.grid.boundsMax;
    result.data = {{"magnetic_strength", scene.initial.magneticStrength},
                   {"time", time},
                   {"kinetic_energy", kinetic},
                   {"magnetic_energy", magnetic},
                   {"cross_helicity", helicity},
                   {"max_relative_energy_drift", result.energyDrift},
                   {"max_relative_cross_helicity_drift", result.helicityDrift},
                   {"extent", {lo[0], hi[0], lo[1], hi[1]}},
                   {"pictures", shots}};
    return result;
}

}  // namespace

StudyResult mhdStudy(const StudyOptions& options) {
    SceneSpec scene = sceneFromText(kMhdRotorScene, "mhd_rotor_2d");
    if (options.quick) {
        scene.grid.resolution = {64, 64, 1};
        scene.basis.velocityModes = {{1, 40}};
        scene.output.frames = 24;
    }
    StudyResult result;
    result.data["scene"] = {{"resolution", {scene.grid.resolution[0], scene.grid.resolution[1]}},
                            {"modes", scene.basis.velocityCount()},
                            {"dt", scene.simulation.dt},
                            {"integrator", "midpoint"}};
    options.note("the rotor with the field, B0 = " +
                 std::to_string(scene.initial.magneticStrength));
    const MhdRun field = runMhd(scene, options, true);
    scene.initial.magneticStrength = 0.0;
    options.note("the rotor without a field");
    const MhdRun none = runMhd(scene, options, true);
    result.data["runs"] = {field.data, none.data};

    SceneSpec disk = sceneFromText(kMhdDiskScene, "mhd_disk_2d");
    if (options.quick) disk.output.frames = 25;
    options.note("a random flow in a random field");
    const MhdRun random = runMhd(disk, options, false);
    result.data["random"] = random.data;
    result.headline = {"random flow and field: largest relative change of the cross helicity",
                       random.helicityDrift, "below 1e-10 (conserved)",
                       random.helicityDrift < 1e-10};
    return result;
}

}  // namespace modeflow::validate
