#pragma once
/// @file RunMemory.h
/// The peak memory of a simulation run, estimated before any work from the smoke grid and the
/// basis. The model (bytes; V velocity DOFs, K modes, cells of the smoke grid = grid cells ×
/// resolution_scale^dim):
///   program       48 MiB (CPU reference) or 150 MiB (a Vulkan device: lavapipe's driver; its
///                 device memory is host memory)
///   basis         3 × (column bytes + coefficient bytes): the cache, the dynamics' coefficients,
///                 the device's copies; the columns V·K·8 and the vorticity quadrature 120·V (a
///                 closed-form basis has neither: its transforms' buffers, counted as 8 face
///                 fields, V·64), the coefficients K²(K−1)/2·8 dense, 20 bytes per non-zero
///                 sparse, none tensor-free
///   smoke         150 (CPU reference: double fields, back-traces, MacCormack temporaries, frames)
///                 or 200 (device: float fields, their staging, frames) bytes per smoke cell
///   particles     256 bytes per particle the shot emits (the state, its copy read back for a
///                 frame, the checkpoint's and the PLY file's bytes)
/// times 1.15. Measured peaks of `modeflow run` (2D disk 128² with 40 and 200 modes, smoke scales
/// 1–8; 3D ball 32³ with 40 and 150 modes, scales 1–3; both devices) are 0.60–0.83 of it.
/// A run's stages name themselves when an allocation fails despite it (inRunStage).

#include <cstdint>
#include <new>
#include <string>

#include "engine/core/AvailableMemory.h"

namespace modeflow {

struct RunMemory {
    double basisBytes = 0.0;
    double smokeBytes = 0.0;
    double particleBytes = 0.0;
    double peakBytes = 0.0;  ///< everything, with the margin
};

/// `device`: a Vulkan device runs it (else the CPU reference); `particles`: the most the run
/// holds (ParticleEmission::capacity).
RunMemory estimateRunMemory(std::int64_t smokeCells, double columnBytes, double coefficientBytes,
                            std::int64_t particles, bool device);

/// The bytes of dense packed coefficients of `modes` modes, K²(K−1)/2·8.
double denseCoefficientBytes(int modes);

/// What to lower when a run does not fit.
inline constexpr const char* kRunMemoryAdvice =
    "lower [smoke].resolution_scale, [grid].resolution or the velocity modes in [basis]";

/// `work()`; a std::bad_alloc inside it becomes "out of memory in <stage> (the estimated peak
/// was X); <advice>".
template <typename Work>
decltype(auto) inRunStage(const std::string& stage, const RunMemory& estimate, Work&& work) {
    try {
        return work();
    } catch (const std::bad_alloc&) {
        throw outOfMemoryIn(stage, estimate.peakBytes, kRunMemoryAdvice);
    }
}

}  // namespace modeflow
