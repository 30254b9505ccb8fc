#include "engine/kernels/SmokeAdvection.h"

#include <algorithm>
#include <array>
#include <cmath>
// The generated header uses uint32_t without including <cstdint>.
#include <cstdint>
#include <string>

#include "engine/format/Error.h"
#include "engine/kernels/SmokeState.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SmokeAdvectParams.h"
#include "shaders/smoke_advect.spv.h"

namespace modeflow::vulkan {
namespace {

shaders::SmokeAdvectParams stepParams(const SmokeState& state, double dt) {
    const MacGrid& basis = state.basisGrid();
    const MacGrid& smoke = state.smokeGrid();
    shaders::SmokeAdvectParams p{};
    p.cellsX = std::uint32_t(smoke.cells[0]);
    p.cellsY = std::uint32_t(smoke.cells[1]);
    p.cellsZ = std::uint32_t(smoke.cells[2]);
    p.cellCount = std::uint32_t(smoke.cellCount());
    p.basisX = std::uint32_t(basis.cells[0]);
    p.basisY = std::uint32_t(basis.cells[1]);
    p.basisZ = std::uint32_t(basis.cells[2]);
    p.dim = std::uint32_t(basis.dim);
    p.faceOffsetY = std::uint32_t(basis.faceOffset(1));
    p.faceOffsetZ = std::uint32_t(basis.faceOffset(2));
    p.scale = std::uint32_t(state.scale());
    p.emitterCount = state.emitterCount();
    // Velocity times dt / spacing: smoke cells per step, as in the CPU reference.
    p.stepX = float(dt / smoke.spacing[0]);
    p.stepY = float(dt / smoke.spacing[1]);
    p.stepZ = smoke.dim == 3 ? float(dt / smoke.spacing[2]) : 0.0f;
    p.dt = float(dt);
    p.originX = float(smoke.origin[0]);
    p.originY = float(smoke.origin[1]);
    p.originZ = float(smoke.origin[2]);
    p.spacingX = float(smoke.spacing[0]);
    p.spacingY = float(smoke.spacing[1]);
    p.spacingZ = float(smoke.spacing[2]);
    return p;
}

}  // namespace

SmokeAdvectionKernels::SmokeAdvectionKernels(const VulkanContext& context, std::uint32_t workgroupSize)
    : mContext(context),
      mKernel(context, ComputeKernelSpec{"smoke_advect", smoke_advect_spv, 9, sizeof(shaders::SmokeAdvectParams),
                                         workgroupSize}) {}

void SmokeAdvectionKernels::record(CommandSequence& sequence, SmokeState& state, const DeviceBuffer& velocity,
                                   double dt, AdvectionScheme scheme) const {
    const std::int64_t faces = state.basisGrid().faceTotal();
    if (velocity.bytes() < VkDeviceSize(faces) * sizeof(float))
        throw Error("smoke_advect: velocity buffer \"" + velocity.name() + "\" holds " +
                    std::to_string(velocity.bytes()) + " bytes, the basis grid's " + std::to_string(faces) +
                    " faces need " + std::to_string(faces * sizeof(float)));
    if (!std::isfinite(dt)) throw Error("smoke_advect: time step " + std::to_string(dt) + " is not finite");
    const std::int64_t cells = state.cellCount();
    if (cells >= (std::int64_t(1) << 32))
        throw Error("smoke_advect: " + std::to_string(cells) + " smoke cells, at most 2^32 - 1 supported");

    shaders::SmokeAdvectParams params = stepParams(state, dt);
    // Bindings 0-8 of smoke_advect.comp.
    const std::array<const DeviceBuffer*, 9> buffers{&velocity,           &state.mask(),
                                                     &state.emitters(),   &state.density(),
                                                     &state.temperature(), &state.densityHat(),
                                                     &state.temperatureHat(), &state.nextDensity(),
                                                     &state.nextTemperature()};
    const std::int64_t groupSize = mKernel.workgroupSize();
    const std::int64_t perDispatch = std::int64_t(mContext.properties().limits.maxComputeWorkGroupCount[0]) * groupSize;
    const auto dispatchAll = [&](std::uint32_t stage) {
        params.stage = stage;
        for (std::int64_t first = 0; first < cells; first += perDispatch) {
            params.firstCell = std::uint32_t(first);
            const std::int64_t count = std::min(perDispatch, cells - first);
            sequence.dispatch(mKernel, buffers, params, std::uint32_t((count + groupSize - 1) / groupSize));
        }
    };
    if (scheme == AdvectionScheme::SemiLagrangian) {
        dispatchAll(SMOKE_STAGE_SEMI_LAGRANGIAN);
    } else {
        dispatchAll(SMOKE_STAGE_MACCORMACK_FORWARD);
        dispatchAll(SMOKE_STAGE_MACCORMACK_CORRECT);
    }
    state.flip();
}

}  // namespace modeflow::vulkan
