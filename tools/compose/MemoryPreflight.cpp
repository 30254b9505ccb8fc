#include "tools/compose/MemoryPreflight.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "engine/core/AvailableMemory.h"
#include "engine/simulation/ParticleEmission.h"
#include "precompute/PrecomputeMemory.h"
#include "precompute/closedform/ClosedFormCoefficients.h"

namespace modeflow {

RunMemory requireRunMemory(const SceneSpec& scene, BackendKind backend) {
    const GridSpec& grid = scene.grid;
    const bool device = backend == BackendKind::Vulkan;
    std::int64_t smokeCells = 1;
    for (int a = 0; a < grid.dim; ++a)
        smokeCells *= std::int64_t{grid.resolution[a]} * scene.smoke.resolutionScale;
    const int modes = scene.basis.velocityCount();
    // A closed-form basis (whole box, free slip) has sparse coefficients and no columns: its
    // transforms' buffers are a few face fields.
    const bool closedForm = hasClosedFormVelocity(scene);
    const PrecomputeMemory precompute = estimatePrecomputeMemory(scene);
    const auto dofs = double(precompute.velocityDofs);
    const double coefficientBytes =
        closedForm          ? kSparseEntryBytes * estimatedClosedFormNonZeros(grid.dim, modes)
        : precompute.tensor ? denseCoefficientBytes(modes)
                            : 0.0;  // tensor-free
    // An eigensolved basis: its columns and its vorticity quadrature (120 bytes a face).
    const double columnBytes = closedForm ? 8.0 * 8.0 * dofs : (8.0 * modes + 120.0) * dofs;
    // Every particle the shot emits (refused here, before any work, beyond maxParticles).
    const std::int64_t particles =
        ParticleEmission(scene.particles, double(scene.output.frames) * scene.output.stepsPerFrame *
                                              scene.simulation.dt)
            .capacity();
    const RunMemory memory =
        estimateRunMemory(smokeCells, columnBytes, coefficientBytes, particles, device);
    const bool smoke = memory.smokeBytes > memory.basisBytes;
    const bool points = memory.particleBytes > std::max(memory.basisBytes, memory.smokeBytes);
    requireMemory(
        memory.peakBytes,
        gridResolutionText(grid) +
            " with [smoke].resolution_scale = " + std::to_string(scene.smoke.resolutionScale) +
            " (" + std::to_string(smokeCells) + " smoke cells)" + (particles > 0 ? ", " : " and ") +
            std::to_string(scene.basis.velocityCount()) + " velocity modes" +
            (particles > 0 ? " and " + std::to_string(particles) + " particles" : ""),
        std::string("the run") + (device ? " on a Vulkan device" : " on the CPU reference"),
        points  ? "lower the count or rate of the [[particles]] sets"
        : smoke ? "lower [smoke].resolution_scale or [grid].resolution"
                : "lower the velocity modes in [basis] or [grid].resolution");
    return memory;
}

}  // namespace modeflow
