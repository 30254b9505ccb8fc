#include "precompute/PrecomputeMemory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "engine/core/AvailableMemory.h"
#include "engine/core/Error.h"
#include "precompute/CoefficientChoice.h"
#include "precompute/closedform/ClosedFormBasis.h"
#include "precompute/closedform/ClosedFormCoefficients.h"
#include "precompute/geometry/Domain.h"
#include "precompute/geometry/ObjMesh.h"
#include "precompute/solve/BlockLanczos.h"
#include "precompute/solve/EigenMethod.h"
#include "precompute/solve/ProcessGroup.h"

namespace modeflow {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;
/// The binary and its libraries before any work: 64 MiB measured for an 8² precompute since
/// PETSc, MPI and MUMPS are linked (40 MiB before).
constexpr double kProgram = 72.0 * kMiB;
constexpr double kMargin = 1.15;
constexpr int kSamplesPerAxis = 64;

/// What the stages' memory depends on; DOF counts as doubles (estimates).
struct Counts {
    int dim = 2;
    double cells = 0.0, velocity = 0.0, scalar = 0.0;
    double highest = 0.0;        ///< velocity modes computed (the highest wanted)
    double kept = 0.0;           ///< velocity modes stored
    double scalarModes = 0.0;    ///< scalar modes stored
    double scalarRequest = 0.0;  ///< scalar eigenpairs computed (the first Neumann ones at least)
    bool tensor = true;  ///< structural coefficients assembled (precompute/CoefficientChoice.h)
    bool closedForm = false;  ///< whole box, free slip: descriptors and sparse coefficients
    EigensolverChoice choice = EigensolverChoice::Automatic;
    int ranks = 1;  ///< MPI ranks of the precompute
};

/// The n-vectors an eigensolve holds at its peak: Spectra's Krylov basis (its dimension in
/// precompute/solve/ShiftInvertEigensolver.cpp; slicing's intervals measured alike), the Ritz
/// vectors and their rescaled copy; or block Lanczos's search space of twice the count with its
/// three working blocks (precompute/solve/BlockLanczos.cpp) and the Ritz vectors, rescaled in place
/// once the space is freed.
double heldVectors(double n, double count, EigenMethod method) {
    if (method == EigenMethod::BlockLanczos) {
        const double block = double(BlockLanczosRequest{}.blockSize);
        return std::min(n, count + std::max(count, 4.0 * block)) + 3.0 * block + count;
    }
    return std::min(n, std::max(std::floor(1.5 * count) + 1.0, count + 30.0)) + 2.0 * count;
}

/// Entries of the Cholesky factor of an operator on n unknowns with CHOLMOD's fill-reducing
/// ordering: n^{4/3} in 3D and n·log n in 2D (nested dissection), constants fitted to CHOLMOD's
/// lnz on the disks and balls of the header (velocity: 8.9–11.4 and 3.0–3.8, scalar: 4.1–5.0 and
/// 1.5–1.9).
double factorEntries(int dim, double n, bool velocity) {
    if (dim == 3) return (velocity ? 11.0 : 5.5) * std::pow(n, 4.0 / 3.0);
    return (velocity ? 4.0 : 2.0) * n * std::log2(std::max(n, 2.0));
}

double eigensolveBytes(int dim, double n, double count, bool velocity, EigenMethod method) {
    if (n < 1.0 || count < 1.0) return 0.0;
    if (method == EigenMethod::Dense) return 3.0 * n * n * 8.0;  // the matrix, its vectors, a copy
    const double operatorRow = dim == 3 ? (velocity ? 14.6 : 7.0) : (velocity ? 9.0 : 5.0);
    return n * heldVectors(n, count, method) * 8.0 + 13.0 * factorEntries(dim, n, velocity) +
           24.0 * operatorRow * n;
}

/// The eigensolve of n unknowns by the method the precompute will choose.
double eigensolveBytes(const Counts& c, double n, double count, bool velocity) {
    const auto method = chooseEigenMethod(std::int64_t(n), std::int64_t(count), c.choice, c.ranks);
    return eigensolveBytes(c.dim, n, count, velocity, method);
}

struct Peak {
    double bytes = 0.0;
    const char* stage = "";
};

/// A closed-form precompute (precompute/closedform): the DOF arrays and the coefficients, 20 bytes
/// per non-zero, written in place and streamed to the cache file (no copy of either).
Peak closedFormPeakOf(const Counts& c) {
    const double dofs = 24.0 * c.velocity + 32.0 * c.cells;
    const double coefficients = kSparseEntryBytes * estimatedClosedFormNonZeros(c.dim, int(c.kept));
    return {kMargin * (kProgram + dofs + coefficients), "structural coefficients"};
}

Peak peakOf(const Counts& c) {
    if (c.closedForm) return closedFormPeakOf(c);
    const bool three = c.dim == 3;
    const double resident =
        three ? 310.0 * c.cells + 490.0 * c.velocity : 50.0 * c.cells + 300.0 * c.velocity;
    const double scalarModes = 3.0 * c.scalar * c.scalarModes * 8.0;
    const double packed = c.tensor ? c.kept * c.kept * (c.kept - 1.0) / 2.0 * 8.0 : 0.0;
    const double elements = c.tensor ? c.velocity / c.dim : 0.0;  // vorticity elements of one type
    // The quadrature: about one vorticity element per face, 8 entries of 12 bytes and 3 row starts.
    const double quadrature = 120.0 * c.velocity;
    const double cache = c.velocity * c.kept * 8.0 + c.scalar * c.scalarModes * 8.0 + packed +
                         quadrature + 8.0 * c.cells + 24.0 * c.velocity + 16.0 * c.scalar;
    const Peak stages[] = {
        {(three ? 430.0 : 280.0) * c.cells, "domain and cut-cell measures"},
        {resident + eigensolveBytes(c, c.scalar, c.scalarRequest, false), "scalar eigensolve"},
        {resident + scalarModes + eigensolveBytes(c, c.velocity, c.highest, true),
         "velocity eigensolve"},
        {resident + scalarModes + 2.0 * c.velocity * c.kept * 8.0 + 1.6 * packed +
             2.0 * quadrature + elements * (3.0 * c.kept + 256.0) * 8.0,
         "structural coefficients"},
        {3.0 * cache, "write cache"}};
    Peak peak = *std::max_element(std::begin(stages), std::end(stages),
                                  [](const Peak& a, const Peak& b) { return a.bytes < b.bytes; });
    peak.bytes = kMargin * (kProgram + peak.bytes);
    return peak;
}

/// Fraction of the grid's cells that reach into Ω, sampled at the cell centres of a lattice of at
/// most kSamplesPerAxis points per axis (mesh shapes at that lattice's resolution): a cell
/// reaches a boundary of normal n up to Σ_a |n_a| h_a/2 from its centre, on average over
/// directions (2/π)·Σ h_a/2 in 2D and ½·Σ h_a/2 in 3D.
double cutCellFraction(const SceneSpec& scene) {
    const GridSpec& grid = scene.grid;
    std::array<int, 3> samples{1, 1, 1};
    double coarsest = 0.0, reach = 0.0;
    for (int a = 0; a < grid.dim; ++a) {
        samples[a] = std::min(grid.resolution[a], kSamplesPerAxis);
        coarsest = std::max(coarsest, (grid.boundsMax[a] - grid.boundsMin[a]) / samples[a]);
        reach += 0.5 * grid.spacing(a) * (grid.dim == 2 ? 2.0 / M_PI : 0.5);
    }
    const Domain domain(scene.domain, grid.dim, 0.5 * coarsest);
    if (domain.isWholeBox()) return 1.0;
    long inside = 0;
    Vec3 p{0.0, 0.0, 0.0};
    for (int k = 0; k < samples[2]; ++k)
        for (int j = 0; j < samples[1]; ++j)
            for (int i = 0; i < samples[0]; ++i) {
                const std::array<int, 3> index{i, j, k};
                for (int a = 0; a < grid.dim; ++a)
                    p[a] = grid.boundsMin[a] +
                           (index[a] + 0.5) * (grid.boundsMax[a] - grid.boundsMin[a]) / samples[a];
                inside += domain.chi(p) > -reach;
            }
    return double(inside) / double(samples[0] * samples[1] * samples[2]);
}

}  // namespace

std::string gridResolutionText(const GridSpec& grid) {
    std::string text = "[grid].resolution = [";
    for (int a = 0; a < grid.dim; ++a) text += (a ? ", " : "") + std::to_string(grid.resolution[a]);
    return text + "]";
}

namespace {

/// A surface scene (V vertices, E ≈ 3V edges, T ≈ 2V triangles, N the highest mode, M scalar
/// modes): the eigensolve (dense below 1200 vertices: three V² matrices; else the grid's 2D
/// model of Lanczos and CHOLMOD on V unknowns), or the modes and coefficients, as in the header.
PrecomputeMemory estimateSurfaceMemory(const SceneSpec& scene) {
    double v = 0.0;
    try {
        v = double(readObjMesh(scene.surface->meshFile).vertices.size());
    } catch (const Error& e) {
        throw Error("[surface].mesh: " + std::string(e.what()));
    }
    const double n = scene.basis.highestVelocityMode(), m = scene.basis.scalarModes;
    const double count = std::max(n, m) + 1.0;
    const double eigensolve = v <= 1200.0 ? 3.0 * v * v * 8.0
                                          : v * (1.5 * count + 2.0 * count) * 8.0 +
                                                13.0 * 2.0 * v * std::log2(std::max(v, 2.0)) * 8.0;
    const double coefficients = 2.0 * 3.0 * v * n * 8.0 + 1.6 * n * n * (n - 1.0) / 2.0 * 8.0 +
                                2.0 * v * (3.0 * n + 256.0) * 8.0;
    PrecomputeMemory memory;
    memory.velocityDofs = std::int64_t(3.0 * v);
    memory.scalarDofs = std::int64_t(v);
    const bool solveIsLarger = eigensolve > coefficients;
    memory.peakStage = solveIsLarger ? "surface eigensolve" : "structural coefficients";
    memory.peakBytes =
        1.15 * (40.0 * 1024 * 1024 + std::max(eigensolve, coefficients) + 3.0 * v * m * 8.0);
    memory.gridBytes = memory.peakBytes;
    return memory;
}

}  // namespace

PrecomputeMemory estimatePrecomputeMemory(const SceneSpec& scene) {
    if (scene.isSurface()) return estimateSurfaceMemory(scene);
    const GridSpec& grid = scene.grid;
    const BasisSpec& basis = scene.basis;
    Counts c;
    c.dim = grid.dim;
    c.cells = 1.0;
    for (int a = 0; a < grid.dim; ++a) c.cells *= grid.resolution[a];
    // Each cell of Ω brings its faces on one side per axis (those on the far side of Ω are walls).
    c.scalar = std::round(cutCellFraction(scene) * c.cells);
    c.velocity = c.dim * c.scalar;
    c.highest = basis.highestVelocityMode();
    c.kept = basis.velocityCount();
    c.scalarModes = basis.scalarModes;
    // One constant per component is computed and dropped; the first Neumann modes always are.
    c.scalarRequest = std::max(basis.scalarModes, 1) + 1;
    c.closedForm = hasClosedFormVelocity(scene);
    c.choice = basis.eigensolver;
    c.ranks = currentProcessGroup().size;
    c.tensor =
        c.closedForm ||
        chooseTensor(basis.coefficients, basis.velocityCount(), std::int64_t(c.velocity)).assemble;

    PrecomputeMemory memory;
    memory.velocityDofs = std::int64_t(c.velocity);
    memory.scalarDofs = std::int64_t(c.scalar);
    memory.tensor = c.tensor;
    const Peak peak = peakOf(c);
    memory.peakBytes = peak.bytes;
    memory.peakStage = peak.stage;
    Counts gridOnly = c;
    gridOnly.highest = gridOnly.kept = 1.0;
    gridOnly.scalarModes = 0.0;
    gridOnly.scalarRequest = 2.0;
    memory.gridBytes = peakOf(gridOnly).bytes;
    return memory;
}

PrecomputeMemory requirePrecomputeMemory(const SceneSpec& scene) {
    const PrecomputeMemory memory = estimatePrecomputeMemory(scene);
    const std::optional<std::uint64_t> available = availableMemory();
    if (scene.isSurface()) {
        requireMemory(memory.peakBytes,
                      "[surface].mesh with " + std::to_string(memory.scalarDofs) +
                          " vertices and velocity modes up to " +
                          std::to_string(scene.basis.highestVelocityMode()),
                      "the precompute (" + memory.peakStage + ")",
                      "use a coarser mesh or fewer modes in [basis]");
        return memory;
    }
    std::string subject = gridResolutionText(scene.grid);
    std::string advice = "lower [grid].resolution";
    if (available && memory.gridBytes <= double(*available)) {
        subject +=
            " with velocity modes up to " + std::to_string(scene.basis.highestVelocityMode());
        if (scene.basis.scalarModes > 0)
            subject += " and " + std::to_string(scene.basis.scalarModes) + " scalar modes";
        advice = "lower the mode counts in [basis] or [grid].resolution";
    }
    requireMemory(memory.peakBytes, subject, "the precompute (" + memory.peakStage + ")", advice);
    return memory;
}

}  // namespace modeflow
