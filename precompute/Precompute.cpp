#include "precompute/Precompute.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <new>
#include <sstream>

#include <unistd.h>

#include "engine/core/AvailableMemory.h"
#include "engine/core/Error.h"
#include "engine/core/WritableDirectory.h"
#include "engine/format/CacheFile.h"
#include "precompute/CoefficientChoice.h"
#include "precompute/PrecomputeMemory.h"
#include "precompute/SurfaceStages.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/ClosedFormCoefficients.h"
#include "precompute/closedform/WholeBoxDofs.h"
#include "precompute/coefficients/CoefficientAssembly.h"
#include "precompute/dec/CubicalComplex.h"
#include "precompute/dec/CutCellDec.h"
#include "precompute/dec/CutCellMeasures.h"
#include "precompute/dec/DirichletScalarDec.h"
#include "precompute/geometry/Domain.h"
#include "precompute/solve/ProcessGroup.h"
#include "precompute/solve/SliceCheckpoint.h"
#include "precompute/solve/SpectralBasis.h"
#include "precompute/solve/WindBaseFlows.h"

namespace modeflow {
namespace {

/// Bumped whenever the numerics change what a cache holds for the same inputs.
constexpr const char* kAlgorithmVersion = "cut-cell-dec/3";
constexpr const char* kSurfaceAlgorithmVersion = "surface-dec/1";

std::string fileDigest(const std::filesystem::path& file, const std::string& key) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(key + ": cannot read mesh file " + file.string());
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ostringstream s;
    s << std::hex << std::setw(16) << std::setfill('0') << fnv1a64(bytes) << ":" << bytes.size();
    return s.str();
}

void writeVec(std::ostream& s, const Vec3& v, int dim) {
    s << "[";
    for (int a = 0; a < dim; ++a) s << (a ? "," : "") << v[a];
    s << "]";
}

/// One line per eigensolve, and its factorization/solve split in the cache's timings.
void reportSolver(Progress& progress, const std::string& what, const SolverStats& s,
                  BasisCache& cache) {
    if (s.operations == 0) return;  // dense path: nothing worth reporting
    std::ostringstream line;
    line << std::fixed << std::setprecision(2) << "  " << what << ": " << s.operations
         << " shift-invert solves, " << s.restarts << " Krylov restarts, " << s.factorizations
         << (s.factorizations == 1 ? " factorization " : " factorizations ") << s.factorSeconds
         << " s, solves " << s.solveSeconds << " s";
    progress.note(line.str());
    cache.timings.emplace_back(what + "_factorization", s.factorSeconds);
    cache.timings.emplace_back(what + "_solves", s.solveSeconds);
}

}  // namespace

std::string basisKey(const SceneSpec& scene) {
    std::ostringstream s;
    s << std::setprecision(17);
    if (scene.isSurface()) {
        s << "format=" << kCacheFormatVersion << " algorithm=" << kSurfaceAlgorithmVersion << "\n";
        s << "surface mesh=" << fileDigest(scene.surface->meshFile, "[surface].mesh") << "\n";
        s << "basis modes=";
        for (const ModeRange& r : scene.basis.velocityModes) s << r.first << "-" << r.last << ",";
        s << " scalar=" << scene.basis.scalarModes << "\n";
        return s.str();
    }
    const GridSpec& g = scene.grid;
    s << "format=" << kCacheFormatVersion << " algorithm=" << kAlgorithmVersion << "\n";
    s << "grid dim=" << g.dim << " resolution=[";
    for (int a = 0; a < g.dim; ++a) s << (a ? "," : "") << g.resolution[a];
    s << "] min=";
    writeVec(s, g.boundsMin, g.dim);
    s << " max=";
    writeVec(s, g.boundsMax, g.dim);
    s << " periodic=[";
    for (int a = 0; a < g.dim; ++a) s << (a ? "," : "") << int(g.periodic[a]);
    s << "]";
    if (g.anyOpen()) {
        s << " open=[";
        for (int side = 0; side < 2 * g.dim; ++side) s << (side ? "," : "") << int(g.open[side]);
        s << "]";
    }
    s << "\n";
    int index = 0;
    for (const ShapeSpec& d : scene.domain) {
        ++index;
        s << "domain kind=" << int(d.kind) << " op=" << int(d.op) << " center=";
        writeVec(s, d.center, g.dim);
        s << " radius=" << d.radius << " radii=";
        writeVec(s, d.radii, g.dim);
        s << " min=";
        writeVec(s, d.min, g.dim);
        s << " max=";
        writeVec(s, d.max, g.dim);
        s << " half_height=" << d.halfHeight << " major=" << d.majorRadius
          << " minor=" << d.minorRadius;
        if (d.kind == ShapeKind::Mesh)
            s << " mesh="
              << fileDigest(d.meshFile, "[[domain]] #" + std::to_string(index) + " (mesh).file");
        s << "\n";
    }
    const BasisSpec& b = scene.basis;
    s << "basis modes=";
    for (const ModeRange& r : b.velocityModes) s << r.first << "-" << r.last << ",";
    s << " scalar=" << b.scalarModes << " scalar_boundary=" << int(b.scalarBoundary)
      << " wall=" << int(b.wall) << " boundary=" << int(b.boundary)
      << " subsamples=" << b.subsamples << "\n";
    return s.str();
}

std::filesystem::path cachePath(const std::string& key, const std::filesystem::path& cacheDir) {
    std::ostringstream name;
    name << std::hex << std::setw(16) << std::setfill('0') << fnv1a64(key) << ".mfbasis";
    return cacheDir / name.str();
}

namespace {

/// An allocation that failed in `stage` despite the estimate made before the precompute.
Error outOfMemory(const std::string& stage, const PrecomputeMemory& estimate) {
    return outOfMemoryIn(stage, estimate.peakBytes,
                         "lower [grid].resolution or the mode counts in [basis]");
}

/// A whole box with free-slip walls: both bases in closed form and their coefficients by
/// selection rules; nothing is measured or solved.
void closedFormStages(const SceneSpec& scene, BasisCache& cache, Progress& progress) {
    const BasisSpec& basis = scene.basis;
    if (basis.coefficients == CoefficientStorage::TensorFree)
        throw Error(
            "[basis].coefficients = \"tensor-free\": a whole box with free-slip walls gets "
            "closed-form "
            "bases, whose coefficients are sparse by selection rules and which have no vorticity "
            "quadrature; use \"auto\" (or \"dense\", \"sparse\")");
    progress.begin("operators");
    fillWholeBoxDofs(cache);
    cache.timings.emplace_back("operators", progress.end());

    progress.begin("closed-form scalar basis");
    cache.scalar.source = BasisSource::ClosedForm;
    cache.scalar.boundary = basis.scalarBoundary;
    cache.scalar.cells = cache.cells;
    cache.scalar.cellStar = cache.cellStar;
    ClosedFormScalar scalar =
        closedFormScalarBasis(scene.grid, basis.scalarModes, basis.scalarBoundary);
    cache.scalar.eigenvalues = scalar.eigenvalues;
    cache.scalar.separable = std::move(scalar.modes);
    cache.scalar.omittedConstants = scalar.omittedConstants;
    cache.timings.emplace_back("closed_form_scalar", progress.end());

    progress.begin("closed-form velocity basis");
    ClosedFormVelocity velocity = closedFormVelocityBasis(scene.grid, basis.velocityModes);
    cache.velocity.source = BasisSource::ClosedForm;
    cache.velocity.eigenvalues = velocity.eigenvalues;
    cache.velocity.separable = std::move(velocity.modes);
    cache.velocity.modeNumbers = std::move(velocity.modeNumbers);
    cache.velocity.harmonic = velocity.harmonicCount;
    cache.timings.emplace_back("closed_form_velocity", progress.end());

    progress.begin("structural coefficients");
    cache.coefficients = assembleClosedFormCoefficients(scene.grid, cache.velocity.separable);
    cache.timings.emplace_back("coefficients", progress.end());
}

/// The stages of the pipeline for a key already computed (hashing mesh files once per run).
BasisCache computeStages(const SceneSpec& scene, std::string key, Progress& progress,
                         BasisMethod method, const IntervalCheckpoints& checkpoints) {
    BasisCache cache;
    cache.key = std::move(key);
    cache.grid = scene.grid;
    cache.wall = scene.basis.wall;
    cache.boundary = scene.basis.boundary;
    // Under mpirun only the eigensolves are shared by the ranks; rank 0 alone does the rest.
    const bool primary = currentProcessGroup().primary();
    if (method == BasisMethod::Automatic && hasClosedFormVelocity(scene)) {
        if (primary) closedFormStages(scene, cache, progress);
        return cache;
    }
    const GridSpec& grid = scene.grid;
    const int n = grid.dim;

    progress.begin("domain and cut-cell measures");
    double hMin = grid.spacing(0);
    for (int a = 1; a < n; ++a) hMin = std::min(hMin, grid.spacing(a));
    const Domain domain(scene.domain, n, 0.5 * hMin);
    const CubicalComplex complex(grid);
    const CutCellMeasures measures =
        measureCutCells(complex, domain, scene.basis.boundary, scene.basis.subsamples);
    cache.timings.emplace_back("measures", progress.end());

    progress.begin("operators");
    const CutCellDec dec = buildCutCellDec(complex, measures, scene.basis.wall);
    if (dec.cells.size() == 0)
        throw Error(
            "[[domain]]: no part of the domain lies inside the grid box; check the "
            "shapes against [grid].bounds_min/bounds_max");
    if (dec.faces.size() == 0)
        throw Error(
            "[[domain]]: the domain is thinner than one grid cell everywhere; refine "
            "[grid].resolution");
    cache.cellFraction = measures.fraction[n];
    cache.faces = dec.faces.toGlobal;
    cache.faceStar = dec.faceStar;
    cache.cells = dec.cells.toGlobal;
    cache.cellStar = dec.cellStar;
    cache.timings.emplace_back("operators", progress.end());

    auto counter = [&progress](long ops) { progress.update(std::to_string(ops) + " solves"); };

    // Scalars first: the first Neumann eigenvalue sets the velocity solve's grad-div penalty.
    progress.begin("scalar eigensolve");
    const BasisSpec& basis = scene.basis;
    cache.scalar.boundary = basis.scalarBoundary;
    const bool neumannBasis = basis.scalarBoundary == ScalarBoundary::Neumann;
    const ScalarBasisResult firstNeumann =
        solveNeumannScalarBasis(dec, neumannBasis ? std::max(1, basis.scalarModes) : 1, counter,
                                basis.eigensolver, checkpoints);
    ScalarBasisResult scalar;
    if (neumannBasis) {
        scalar = firstNeumann;
        cache.scalar.cells = dec.cells.toGlobal;
        cache.scalar.cellStar = dec.cellStar;
    } else if (basis.scalarModes > 0) {
        const DirichletScalarDec ddec = buildDirichletScalarDec(complex, domain, basis.boundary);
        scalar = solveDirichletScalarBasis(ddec, basis.scalarModes, counter, basis.eigensolver,
                                           checkpoints);
        cache.scalar.cells = ddec.cells.toGlobal;
        cache.scalar.cellStar = ddec.cellStar;
    }
    const int keep = basis.scalarModes;
    cache.scalar.eigenvalues =
        scalar.eigenvalues.head(std::min<Eigen::Index>(keep, scalar.eigenvalues.size()));
    cache.scalar.modes = scalar.modes.leftCols(cache.scalar.eigenvalues.size());
    cache.scalar.omittedConstants = scalar.omittedConstants;
    SolverStats scalarStats = firstNeumann.stats;
    if (!neumannBasis) scalarStats += scalar.stats;
    reportSolver(progress, "scalar", scalarStats, cache);
    cache.timings.emplace_back("scalar_eigensolve", progress.end());

    progress.begin("velocity eigensolve");
    const VelocityBasisResult velocity =
        solveVelocityBasis(dec, basis.velocityModes, firstNeumann.eigenvalues[0],
                           domainMeasure(dec.cellStar), counter, basis.eigensolver, checkpoints);
    cache.velocity.eigenvalues = velocity.eigenvalues;
    cache.velocity.modes = velocity.modes;
    cache.velocity.modeNumbers = velocity.modeNumbers;
    cache.velocity.harmonic = velocity.harmonicCount;
    cache.velocity.penalty = velocity.penalty;
    reportSolver(progress, "velocity", velocity.stats, cache);
    cache.timings.emplace_back("velocity_eigensolve", progress.end());

    if (!primary) return cache;
    progress.begin("structural coefficients");
    cache.quadrature = vorticityQuadrature(complex, measures, dec);
    const int modes = int(cache.velocity.modes.cols());
    const TensorChoice choice =
        chooseTensor(basis.coefficients, modes, std::int64_t(dec.faces.size()));
    if (choice.assemble) {
        cache.coefficients = storedCoefficients(
            basis.coefficients,
            assembleStructuralCoefficients(cache.quadrature, cache.velocity.modes), modes);
    } else {
        cache.coefficients.storage = BasisCache::Coefficients::Storage::None;
        progress.note(
            "  structural coefficients: none assembled, the advection is evaluated "
            "tensor-free (" +
            choice.reason + ")");
    }
    cache.timings.emplace_back("coefficients", progress.end());
    // Walls inside the box: the held flow a wind makes around them, for a run with a [wind].
    if (!scene.domain.empty()) {
        progress.begin("wind base flows");
        cache.windBase = windBaseFlows(complex, measures, dec);
        cache.windStokes = windStokesCorrections(complex, dec, cache.velocity.modes,
                                                 cache.velocity.eigenvalues, cache.windBase);
        cache.timings.emplace_back("wind_base_flows", progress.end());
    }
    return cache;
}

/// The pipeline, refused before any work when the estimate does not fit in memory.
BasisCache computeBasis(const SceneSpec& scene, std::string key, Progress& progress,
                        const PrecomputeMemory& estimate, BasisMethod method,
                        const IntervalCheckpoints& checkpoints) {
    try {
        if (scene.isSurface()) {
            BasisCache cache = computeSurfaceStages(scene, std::move(key), progress);
            cache.coefficients =
                storedCoefficients(scene.basis.coefficients, std::move(cache.coefficients.packed),
                                   int(cache.velocity.modes.cols()));
            return cache;
        }
        return computeStages(scene, std::move(key), progress, method, checkpoints);
    } catch (const std::bad_alloc&) {
        throw outOfMemory(progress.stage(), estimate);
    }
}

}  // namespace

BasisCache computeBasis(const SceneSpec& scene, Progress& progress, BasisMethod method) {
    const PrecomputeMemory estimate = requirePrecomputeMemory(scene);
    return computeBasis(scene, basisKey(scene), progress, estimate, method, {});
}

CacheOutcome ensureCache(const SceneSpec& scene, const std::filesystem::path& cacheDir, bool force,
                         Progress& progress) {
    ensureWritableDirectory(cacheDir, "cache directory",
                            "; choose another with --cache-dir or MODEFLOW_CACHE_DIR");

    const std::string key = basisKey(scene);
    CacheOutcome outcome{cachePath(key, cacheDir), false, {}};
    if (!force && std::filesystem::exists(outcome.path)) {
        try {
            outcome.cache = readCache(outcome.path);
            outcome.reused = outcome.cache.key == key;
            if (!outcome.reused)
                progress.note("cache " + outcome.path.string() +
                              " belongs to other inputs; rebuilding");
        } catch (const Error& e) {
            progress.note(std::string(e.what()) + "; rebuilding");
        }
    }
    if (outcome.reused) {
        // A cache made tensor-free gets the tensor a scene now asks for, once.
        if (completeCoefficients(outcome.cache, scene.basis.coefficients, progress)) {
            progress.begin("write cache");
            writeCache(outcome.path, outcome.cache);
            progress.end();
        }
        return outcome;
    }
    const PrecomputeMemory estimate = requirePrecomputeMemory(scene);
    // Sliced eigensolves keep their finished intervals beside the cache until it is written, so
    // that an interrupted precompute resumes from them; unless it is asked to solve afresh.
    if (force && currentProcessGroup().primary()) removeSliceCheckpoints(outcome.path);
    const IntervalCheckpoints checkpoints{
        outcome.path, [&progress](const std::string& message) { progress.note(message); }};
    outcome.cache =
        computeBasis(scene, key, progress, estimate, BasisMethod::Automatic, checkpoints);
    if (!currentProcessGroup().primary()) return outcome;
    progress.begin("write cache");
    try {
        writeCache(outcome.path, outcome.cache);
    } catch (const std::bad_alloc&) {
        throw outOfMemory(progress.stage(), estimate);
    }
    removeSliceCheckpoints(outcome.path);
    progress.end();
    return outcome;
}

}  // namespace modeflow
