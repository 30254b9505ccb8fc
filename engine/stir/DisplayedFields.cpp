#include "engine/stir/DisplayedFields.h"

#include <string>

#include "engine/core/Error.h"
#include "engine/device/Simulation.h"
#include "engine/run/RunInputs.h"
#include "engine/simulation/WindTransport.h"

namespace modeflow::stir {

DisplayedFields::DisplayedFields(const vulkan::VulkanContext& context, const RunInputs& run)
    : mContext(context),
      mBasisGrid(airGridOf(run.cache.grid, run.settings.wind)),
      mSmokeGrid(mBasisGrid.refined(run.settings.smokeScale)) {
    const std::size_t cells = std::size_t(mSmokeGrid.cellCount());
    if (run.smokeMask.size() != cells)
        throw Error("stir display: the smoke mask has " + std::to_string(run.smokeMask.size()) +
                    " entries, the smoke grid " + std::to_string(cells) + " cells");
    mMask.assign((cells + 3) / 4 * 4, 0);
    for (std::size_t c = 0; c < cells; ++c) mMask[c] = run.smokeMask[c] != 0;
}

DisplayedFields::Uploaded& DisplayedFields::uploaded() {
    if (!mUploaded) {
        const VkDeviceSize cells = VkDeviceSize(mSmokeGrid.cellCount());
        mUploaded.emplace(Uploaded{
            vulkan::DeviceBuffer(mContext, cells * 2 * sizeof(float), "displayed smoke"),
            vulkan::DeviceBuffer::fromValues<std::uint8_t>(mContext, mMask, "displayed smoke mask"),
            vulkan::DeviceBuffer(mContext, VkDeviceSize(mBasisGrid.faceTotal()) * sizeof(float),
                                 "displayed face velocity"),
            vulkan::DeviceBuffer(mContext, cells * sizeof(float), "displayed flame")});
    }
    return *mUploaded;
}

display::FieldBuffers DisplayedFields::of(const Simulator& simulation, bool withVelocity) {
    const MacGrid& grid = simulation.smokeGrid();
    if (grid.cellCount() != mSmokeGrid.cellCount() || grid.dim != mSmokeGrid.dim)
        throw Error("stir display: the simulation's smoke grid (" +
                    std::to_string(grid.cellCount()) + " cells) is not the run's (" +
                    std::to_string(mSmokeGrid.cellCount()) + ")");
    // The one place that looks behind the Simulator interface: the device simulation's buffers
    // are already where the display kernels read, so drawing it copies nothing (the window's
    // Backend makes device simulations on the display's context). Every other simulator hands
    // its fields over through the interface.
    if (const auto* onDevice = dynamic_cast<const device::Simulation*>(&simulation)) {
        const device::SmokeState& smoke = onDevice->smokeState();
        return {smoke.fields(),
                smoke.mask(),
                onDevice->faceVelocityBuffer(),
                smoke.smokeGrid(),
                smoke.basisGrid(),
                smoke.fire() ? &smoke.second(device::SmokePair::Fuel) : nullptr};
    }
    Uploaded& buffers = uploaded();
    const SmokeFields smoke = simulation.smoke();
    // (density, temperature) pairs as the device keeps them; 0 outside Ω, as there, so the
    // smoke fades into the walls rather than past them.
    std::vector<float> pairs(2 * smoke.density.size(), 0.0f);
    for (std::size_t c = 0; c < smoke.density.size(); ++c)
        if (mMask[c]) {
            pairs[2 * c] = float(smoke.density[c]);
            pairs[2 * c + 1] = float(smoke.temperature[c]);
        }
    buffers.smoke.upload<float>(pairs);
    if (!smoke.flame.empty()) {
        std::vector<float> flame(smoke.flame.size(), 0.0f);
        for (std::size_t c = 0; c < flame.size(); ++c)
            if (mMask[c]) flame[c] = float(smoke.flame[c]);
        buffers.flame.upload<float>(flame);
    }
    if (withVelocity) {
        const std::vector<double> faces = simulation.faceVelocity();
        if (faces.size() != std::size_t(mBasisGrid.faceTotal()))
            throw Error("stir display: the simulation's face velocity has " +
                        std::to_string(faces.size()) + " values, the basis grid " +
                        std::to_string(mBasisGrid.faceTotal()) + " faces");
        const std::vector<float> narrow(faces.begin(), faces.end());
        buffers.faceVelocity.upload<float>(narrow);
    }
    return {buffers.smoke, buffers.mask, buffers.faceVelocity,
            mSmokeGrid,    mBasisGrid,   smoke.flame.empty() ? nullptr : &buffers.flame};
}

}  // namespace modeflow::stir
