#include "engine/device/ConservativeTransport.h"

#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <string>

#include "engine/core/Error.h"
#include "engine/device/ChunkedDispatch.h"
#include "engine/device/SmokeAdvection.h"
#include "engine/device/SmokeState.h"
#include "engine/simulation/FluxSubsteps.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SmokeFluxParams.h"
#include "shaders/smoke_flux_courant_2d.spv.h"
#include "shaders/smoke_flux_courant_3d.spv.h"
#include "shaders/smoke_flux_step_2d.spv.h"
#include "shaders/smoke_flux_step_3d.spv.h"
#include "shaders/smoke_flux_velocity_2d.spv.h"
#include "shaders/smoke_flux_velocity_3d.spv.h"

namespace modeflow::device {
namespace {

constexpr std::uint32_t kWorkgroupSize = 128;

/// The kernel of one stage of shaders/SmokeFlux.glsl, its read-only inputs as 32-bit values
/// (`floats`), 64-bit words (`words`) or whole texels (`texels`).
vulkan::ComputeKernel fluxKernel(const vulkan::VulkanContext& context, const char* name,
                                 std::span<const std::uint32_t> spirv, std::uint32_t buffers,
                                 std::vector<std::uint32_t> texels,
                                 std::vector<std::uint32_t> words,
                                 std::vector<std::uint32_t> floats) {
    return vulkan::ComputeKernel(context,
                                 vulkan::ComputeKernelSpec{name,
                                                           spirv,
                                                           buffers,
                                                           sizeof(shaders::SmokeFluxParams),
                                                           kWorkgroupSize,
                                                           {},
                                                           std::move(texels),
                                                           std::move(words),
                                                           std::move(floats)});
}

shaders::SmokeFluxParams fluxParams(const SmokeState& state, double dt) {
    const MacGrid& basis = state.basisGrid();
    const MacGrid& smoke = state.smokeGrid();
    shaders::SmokeFluxParams p{};
    setGridParams(p, state);
    p.dim = std::uint32_t(smoke.dim);
    p.smokeFaceOffsetY = std::uint32_t(smoke.faceOffset(1));
    p.smokeFaceOffsetZ = std::uint32_t(smoke.faceOffset(2));
    p.crossable = basis.crossableSideBits();
    p.spacingX = float(smoke.spacing[0]);
    p.spacingY = float(smoke.spacing[1]);
    p.spacingZ = float(smoke.spacing[2]);
    p.dt = float(dt);
    return p;
}

}  // namespace

ConservativeTransport::ConservativeTransport(const vulkan::VulkanContext& context,
                                             const SmokeState& state)
    : mContext(context),
      mDim(state.smokeGrid().dim),
      // Bindings of shaders/SmokeFlux.glsl, stage by stage.
      mVelocity(fluxKernel(context, "smoke_flux_velocity",
                           mDim == 3 ? std::span<const std::uint32_t>(smoke_flux_velocity_3d_spv)
                                     : std::span<const std::uint32_t>(smoke_flux_velocity_2d_spv),
                           3, {}, {0}, {1})),
      mCourant(fluxKernel(context, "smoke_flux_courant",
                          mDim == 3 ? std::span<const std::uint32_t>(smoke_flux_courant_3d_spv)
                                    : std::span<const std::uint32_t>(smoke_flux_courant_2d_spv),
                          2, {}, {}, {0})),
      mStep(fluxKernel(context, "smoke_flux_step",
                       mDim == 3 ? std::span<const std::uint32_t>(smoke_flux_step_3d_spv)
                                 : std::span<const std::uint32_t>(smoke_flux_step_2d_spv),
                       7, {0, 4}, {3}, {1, 2})),
      mFaceVelocity(context,
                    std::max<VkDeviceSize>(vulkan::DeviceBuffer::kTexelBytes,
                                           VkDeviceSize(state.smokeGrid().faceTotal()) * 4),
                    "smoke face velocity"),
      mWorst(context, vulkan::DeviceBuffer::kTexelBytes, "worst Courant number") {}

void ConservativeTransport::recordCourant(vulkan::CommandSequence& sequence,
                                          const SmokeAdvectionKernels& advection,
                                          const SmokeState& state,
                                          const vulkan::DeviceBuffer& velocity, double dt) const {
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw Error("conservative smoke advection: time step " + std::to_string(dt) +
                    " is not positive and finite");
    advection.recordFacePairs(sequence, state, velocity);
    shaders::SmokeFluxParams params = fluxParams(state, dt);
    params.count = std::uint32_t(state.smokeGrid().faceTotal());
    const std::array<const vulkan::DeviceBuffer*, 3> faces{&state.facePairs(), &state.mask(),
                                                           &mFaceVelocity};
    dispatchInChunks(mContext, sequence, mVelocity, faces, params, &shaders::SmokeFluxParams::first,
                     params.count);
    sequence.fill(mWorst, 4, 0u);
    params.count = std::uint32_t(state.cellCount());
    const std::array<const vulkan::DeviceBuffer*, 2> cells{&mFaceVelocity, &mWorst};
    dispatchInChunks(mContext, sequence, mCourant, cells, params, &shaders::SmokeFluxParams::first,
                     params.count);
}

int ConservativeTransport::substeps() const {
    std::array<std::uint32_t, 1> bits{};
    mWorst.download<std::uint32_t>(bits);
    return fluxSubsteps(double(std::bit_cast<float>(bits[0])));
}

void ConservativeTransport::record(vulkan::CommandSequence& sequence, SmokeState& state, double dt,
                                   int substeps) const {
    if (substeps < 1 || substeps > maxFluxSubsteps)
        throw Error("conservative smoke advection: " + std::to_string(substeps) +
                    " substeps, expected 1 to " + std::to_string(maxFluxSubsteps));
    shaders::SmokeFluxParams params = fluxParams(state, dt);
    params.count = state.fluidCellCount();
    params.substep = float(dt / substeps);
    // Substep by substep, every pair: the pairs' fields ping-pong together (SmokeState::flip).
    for (int s = 0; s < substeps; ++s) {
        params.last = s + 1 == substeps ? 1u : 0u;
        for (int p = 0; p < state.pairCount(); ++p) {
            const auto pair = SmokePair(p);
            params.ghostPair = std::uint32_t(p);
            const std::array<const vulkan::DeviceBuffer*, 7> buffers{
                &state.fluidCells(pair), &state.mask(),   &mFaceVelocity,
                &state.fields(pair),     &state.ghosts(), &state.nextFields(pair),
                &state.second(pair)};
            dispatchInChunks(mContext, sequence, mStep, buffers, params,
                             &shaders::SmokeFluxParams::first, params.count);
        }
        state.flip();
    }
}

}  // namespace modeflow::device
