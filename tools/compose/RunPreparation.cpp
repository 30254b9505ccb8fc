#include "tools/compose/RunPreparation.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/core/MacGrid.h"
#include "engine/dynamics/CachedCoefficients.h"
#include "precompute/CoefficientChoice.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/FluidMask.h"
#include "tools/compose/InitialState.h"
#include "tools/compose/MeshSolids.h"
#include "tools/compose/SmokeMask.h"

namespace modeflow {
namespace {

/// Every [[source]] must cover a fluid smoke cell (a moving one at its start or at one of its key
/// frames while it emits): one that emits into none is a typo in its position or size, and
/// would silently add nothing.
void requireSourcesInFluid(const SceneSpec& scene, const RunInputs& run) {
    const MacGrid grid = MacGrid::fromSpec(run.cache.grid).refined(run.settings.smokeScale);
    const auto coversFluid = [&](const SmokeEmitter& emitter) {
        for (int z = 0; z < grid.cells[2]; ++z)
            for (int y = 0; y < grid.cells[1]; ++y)
                for (int x = 0; x < grid.cells[0]; ++x) {
                    if (!run.smokeMask[std::size_t(grid.cellIndex(x, y, z))]) continue;
                    const Vec3 centre{grid.cellCentre(0, x), grid.cellCentre(1, y),
                                      grid.dim == 3 ? grid.cellCentre(2, z) : 0.0};
                    if (emitter.contains(centre, grid)) return true;
                }
        return false;
    };
    for (std::size_t e = 0; e < run.settings.emitters.size(); ++e) {
        const SmokeEmitter& emitter = run.settings.emitters[e];
        std::vector<double> times{emitter.start};
        for (const auto& [t, position] : emitter.path) times.push_back(t);
        for (const RotationKey& key : emitter.rotation) times.push_back(key.time);
        bool covers = false;
        for (const double t : times)
            if (!covers && (t == emitter.start || emitter.activeAt(t)))
                covers = coversFluid(emitter.placedAt(t));
        if (!covers)
            throw Error(scene.sourceFile.string() + ": [[source]] #" + std::to_string(e + 1) +
                        " covers no fluid cell of the smoke grid: it lies outside the domain or is "
                        "smaller than a smoke cell" +
                        (emitter.moves() ? " at its start and at each of its key frames" : "") +
                        "; move it into Ω or enlarge it");
    }
}

void requireFinite(const SceneSpec& scene, const Eigen::VectorXd& state, const char* key) {
    if (!state.allFinite())
        throw Error(scene.sourceFile.string() + ": [initial]." + key +
                    ": the initial state is not finite (too large to represent); lower its energy "
                    "or strength");
}

/// The level sets of a scene's mesh obstacles and mesh sources (MeshSolids.h).
struct SceneSolids {
    ObstacleShapes obstacles;
    std::vector<std::shared_ptr<const SolidLevelSet>> sources;
};

/// Read and checked before the precompute's minutes.
SceneSolids sceneSolids(const SceneSpec& scene) {
    return {obstacleSolids(scene), sourceSolids(scene)};
}

/// Everything after the cache.
void complete(RunInputs& run, RunParts parts, Progress& progress, const SceneSolids& solids) {
    const SceneSpec& scene = run.scene;
    completeCoefficients(run.cache, scene.basis.coefficients, progress);
    run.coefficients = takeCoefficientsFromCache(run.cache, scene.basis.coefficients);
    run.settings = SimulationSettings::fromScene(scene, run.cache);
    attachObstacleSolids(run.settings.obstacles, solids.obstacles);
    attachSourceSolids(run.settings.emitters, solids.sources);
    const int modes = run.coefficients->size();
    run.initialVelocity = initialVelocity(scene, run.cache, modes);
    requireFinite(scene, run.initialVelocity, "velocity");
    if (run.settings.mhd) {
        run.initialMagneticField = initialMagneticField(scene, run.cache, modes);
        requireFinite(scene, run.initialMagneticField, "magnetic");
    }
    if (parts == RunParts::DynamicsAndSmoke) {
        run.smokeMask = run.cachePath.empty()
                            ? fluidMask(scene, run.cache, scene.smoke.resolutionScale)
                            : smokeMaskOf(scene, run.cache, run.cachePath, progress);
        requireSourcesInFluid(scene, run);
    }
}

}  // namespace

RunInputs prepareRun(const SceneSpec& scene, const std::filesystem::path& cacheDir,
                     Progress& progress, RunParts parts) {
    RunInputs run;
    run.scene = scene;
    const SceneSolids solids = sceneSolids(scene);
    CacheOutcome outcome = ensureCache(scene, cacheDir, false, progress);
    run.cachePath = std::move(outcome.path);
    run.cache = std::move(outcome.cache);
    complete(run, parts, progress, solids);
    return run;
}

RunInputs prepareRun(const SceneSpec& scene, BasisCache cache, RunParts parts) {
    RunInputs run;
    run.scene = scene;
    run.cache = std::move(cache);
    Progress quiet = Progress::silent();
    complete(run, parts, quiet, sceneSolids(scene));
    return run;
}

}  // namespace modeflow
