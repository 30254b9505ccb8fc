#include "engine/device/SmokeAdvection.h"

#include <algorithm>
#include <array>
#include <cmath>
// The generated header uses uint32_t without including <cstdint>.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/Error.h"
#include "engine/device/ChunkedDispatch.h"
#include "engine/device/SmokeState.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SmokeAdvectParams.h"
#include "shaders/smoke_advect_correct_2d.spv.h"
#include "shaders/smoke_advect_correct_3d.spv.h"
#include "shaders/smoke_advect_forward_2d.spv.h"
#include "shaders/smoke_advect_forward_3d.spv.h"
#include "shaders/smoke_advect_sl_2d.spv.h"
#include "shaders/smoke_advect_sl_3d.spv.h"
#include "shaders/smoke_face_pairs.spv.h"

namespace modeflow::device {
namespace {

shaders::SmokeAdvectParams stepParams(const SmokeState& state, double dt) {
    const MacGrid& smoke = state.smokeGrid();
    shaders::SmokeAdvectParams p{};
    setGridParams(p, state);
    p.fluidCount = state.fluidCellCount();
    // Velocity times dt / spacing: smoke cells per step, as in the CPU reference.
    p.stepX = float(dt / smoke.spacing[0]);
    p.stepY = float(dt / smoke.spacing[1]);
    p.stepZ = smoke.dim == 3 ? float(dt / smoke.spacing[2]) : 0.0f;
    p.dt = float(dt);
    return p;
}

shaders::SmokeFacePairsParams pairParams(const MacGrid& basis) {
    shaders::SmokeFacePairsParams p{};
    p.faceCount = std::uint32_t(basis.faceTotal());
    p.wrapX = basis.periodic[0] ? std::uint32_t(basis.cells[0]) : 0u;
    return p;
}

/// One of the smoke_advect_<stage>_<dim>d kernels (bindings 0-8 of shaders/SmokeAdvect.glsl):
/// the read-only inputs as texels, and MacCormack's hat and record too in the correction, which
/// reads what the forward stage wrote.
/// `unitScale`: the variant for a smoke grid equal to the basis grid (SmokeAdvect.glsl).
vulkan::ComputeKernel advectKernel(const vulkan::VulkanContext& context, const char* name,
                                   std::span<const std::uint32_t> spirv, std::uint32_t stage,
                                   std::uint32_t workgroupSize, bool unitScale) {
    std::vector<std::uint32_t> texels{1, 8}, words{0, 3}, floats{2};
    if (stage == SMOKE_STAGE_MACCORMACK_CORRECT) {
        texels.push_back(5);
        words.push_back(4);
    }
    return vulkan::ComputeKernel(context,
                                 vulkan::ComputeKernelSpec{name,
                                                           spirv,
                                                           9,
                                                           sizeof(shaders::SmokeAdvectParams),
                                                           workgroupSize,
                                                           {unitScale ? 1u : 0u},
                                                           std::move(texels),
                                                           std::move(words),
                                                           std::move(floats)});
}

/// smoke_face_pairs with its WRAP_X: compiled out for a walled x (an `if` on lavapipe runs its
/// body whichever lanes take it, here integer divisions lane by lane).
vulkan::ComputeKernel facePairsKernel(const vulkan::VulkanContext& context,
                                      std::uint32_t workgroupSize, bool wrapX) {
    return vulkan::ComputeKernel(context,
                                 vulkan::ComputeKernelSpec{"smoke_face_pairs",
                                                           smoke_face_pairs_spv,
                                                           3,
                                                           sizeof(shaders::SmokeFacePairsParams),
                                                           workgroupSize,
                                                           {wrapX ? 1u : 0u},
                                                           {0}});
}

struct StageShader {
    const char* name;
    std::span<const std::uint32_t> spirv;
};

/// By stage (semi-Lagrangian, MacCormack forward, MacCormack correction), 2D then 3D.
const std::array<StageShader, 6> kStageShaders{
    StageShader{"smoke_advect_sl_2d", smoke_advect_sl_2d_spv},
    StageShader{"smoke_advect_forward_2d", smoke_advect_forward_2d_spv},
    StageShader{"smoke_advect_correct_2d", smoke_advect_correct_2d_spv},
    StageShader{"smoke_advect_sl_3d", smoke_advect_sl_3d_spv},
    StageShader{"smoke_advect_forward_3d", smoke_advect_forward_3d_spv},
    StageShader{"smoke_advect_correct_3d", smoke_advect_correct_3d_spv}};

}  // namespace

SmokeAdvectionKernels::SmokeAdvectionKernels(const vulkan::VulkanContext& context,
                                             std::uint32_t workgroupSize)
    : mContext(context.requireShaderInt64("the smoke advection")), mWorkgroupSize(workgroupSize) {}

const vulkan::ComputeKernel& SmokeAdvectionKernels::stageKernel(std::uint32_t stage, int dim,
                                                                bool unitScale) const {
    // The correction samples no velocity: one variant of it.
    const bool variant = unitScale && stage != SMOKE_STAGE_MACCORMACK_CORRECT;
    const std::size_t shader = std::size_t(stage) + (dim == 3 ? 3 : 0);
    std::optional<vulkan::ComputeKernel>& kernel = mStages[2 * shader + (variant ? 1 : 0)];
    if (!kernel)
        kernel.emplace(advectKernel(mContext, kStageShaders[shader].name,
                                    kStageShaders[shader].spirv, stage, mWorkgroupSize, variant));
    return *kernel;
}

void SmokeAdvectionKernels::recordFacePairs(vulkan::CommandSequence& sequence,
                                            const SmokeState& state,
                                            const vulkan::DeviceBuffer& velocity) const {
    const std::int64_t faces = state.basisGrid().faceTotal();
    if (velocity.bytes() < VkDeviceSize(faces) * sizeof(float))
        throw Error("smoke_advect: velocity buffer \"" + velocity.name() + "\" holds " +
                    std::to_string(velocity.bytes()) + " bytes, the basis grid's " +
                    std::to_string(faces) + " faces need " + std::to_string(faces * sizeof(float)));
    shaders::SmokeFacePairsParams pairs = pairParams(state.basisGrid());
    // Bindings 0-2 of shaders/smoke_face_pairs.comp: the velocity as texels and as floats.
    const std::array<const vulkan::DeviceBuffer*, 3> pairBuffers{&velocity, &velocity,
                                                                 &state.facePairs()};
    std::optional<vulkan::ComputeKernel>& facePairs = mFacePairs[pairs.wrapX != 0 ? 1 : 0];
    if (!facePairs) facePairs.emplace(facePairsKernel(mContext, mWorkgroupSize, pairs.wrapX != 0));
    dispatchInChunks(mContext, sequence, *facePairs, pairBuffers, pairs,
                     &shaders::SmokeFacePairsParams::firstFace, (faces + 3) / 4, 4);
}

void SmokeAdvectionKernels::record(vulkan::CommandSequence& sequence, SmokeState& state,
                                   const vulkan::DeviceBuffer& velocity, double dt,
                                   AdvectionScheme scheme) const {
    if (!std::isfinite(dt))
        throw Error("smoke_advect: time step " + std::to_string(dt) + " is not finite");
    if (scheme == AdvectionScheme::Conservative)
        throw Error("smoke_advect: the conservative scheme is device::ConservativeTransport's");
    const std::int64_t cells = state.cellCount();
    if (cells >= (std::int64_t(1) << 32))
        throw Error("smoke_advect: " + std::to_string(cells) +
                    " smoke cells, at most 2^32 - 1 supported");

    recordFacePairs(sequence, state, velocity);
    shaders::SmokeAdvectParams params = stepParams(state, dt);
    // Each pair in turn, through the shared MacCormack buffers.
    for (int p = 0; p < state.pairCount(); ++p) {
        const auto pair = SmokePair(p);
        params.ghostPair = std::uint32_t(p);
        // Bindings 0-8 of shaders/SmokeAdvect.glsl.
        const std::array<const vulkan::DeviceBuffer*, 9> buffers{&state.facePairs(),
                                                                 &state.fluidCells(pair),
                                                                 &state.stencilMask(),
                                                                 &state.fields(pair),
                                                                 &state.hat(),
                                                                 &state.record(),
                                                                 &state.nextFields(pair),
                                                                 &state.second(pair),
                                                                 &state.ghosts()};
        const auto stage = [&](std::uint32_t s) {
            dispatchInChunks(
                mContext, sequence, stageKernel(s, state.smokeGrid().dim, state.scale() == 1),
                buffers, params, &shaders::SmokeAdvectParams::firstCell, state.fluidCellCount());
        };
        if (scheme == AdvectionScheme::SemiLagrangian) {
            stage(SMOKE_STAGE_SEMI_LAGRANGIAN);
        } else {
            stage(SMOKE_STAGE_MACCORMACK_FORWARD);
            stage(SMOKE_STAGE_MACCORMACK_CORRECT);
        }
    }
    state.flip();
}

}  // namespace modeflow::device
