#pragma once
/// @file SmokeState.h
/// The smoke on the device: density and temperature as float32 ping-pong buffers on the smoke
/// grid (basisGrid.refined(scale)), the fluid mask, the emitters, and what the advection kernels
/// read and write on the way (layouts: shaders/SmokeAdvectParams.h; why: shaders/SmokeAdvect.glsl).
/// SmokeAdvectionKernels::record() reads the current fields, writes the others and flips: after
/// recording, current() names what the step will have written, so several steps can be recorded
/// into one submission with no host round trip. Read the fields back only after the submission's
/// fence (CommandSequence::submitAndWait()).
///
/// Cells outside the fluid mask are 0 in every field at all times: upload() drops what it is
/// given there, and the kernels never write them. Every buffer is padded with zeros to whole
/// 16-byte texels, as the kernels read them through texel views (DeviceBuffer::texelView and
/// wordView).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeState {
public:
    /// Fields start at 0. `fluidMask`: one entry per smoke cell, non-zero inside Ω.
    /// @throw modeflow::Error when scale < 1, the mask has the wrong size, the smoke grid has more
    /// than 65535 cells along x or y, or a buffer would exceed the device's texel or storage
    /// buffer limit.
    SmokeState(const vulkan::VulkanContext& context, const MacGrid& basisGrid, int scale,
               std::span<const std::uint8_t> fluidMask);

    const MacGrid& basisGrid() const { return mBasis; }
    const MacGrid& smokeGrid() const { return mSmoke; }
    int scale() const { return mScale; }
    std::int64_t cellCount() const { return mSmoke.cellCount(); }
    /// Cells inside Ω: the advection's invocations.
    std::uint32_t fluidCellCount() const { return mFluidCount; }

    /// Replaces the current fields (one value per smoke cell each; cells outside Ω become 0).
    /// Between submissions only.
    /// @throw modeflow::Error on a wrong size.
    void upload(std::span<const float> density, std::span<const float> temperature);
    /// Copies the current fields out. After the writing submission's fence only.
    void download(std::span<float> densityOut, std::span<float> temperatureOut) const;

    /// The emitters of the following steps: their rates, summed per fluid cell in double
    /// precision with the CPU reference's inside test (applyEmitters), go to the device as
    /// float32. Between submissions only.
    /// @throw modeflow::Error when there are more than maxSmokeEmitters.
    void setEmitters(std::span<const SmokeEmitter> emitters);
    std::uint32_t emitterCount() const { return mEmitterCount; }

    /// Density and temperature interleaved, (density, temperature) per cell: now and next.
    const vulkan::DeviceBuffer& fields() const { return mFields[mCurrent]; }
    const vulkan::DeviceBuffer& nextFields() const { return mFields[1 - mCurrent]; }
    /// The current temperature alone, one float per cell (e.g. for ForceFieldKernel).
    const vulkan::DeviceBuffer& temperature() const { return mTemperature; }
    /// The fluid mask, one byte per cell packed four to a 32-bit word.
    const vulkan::DeviceBuffer& mask() const { return mMask; }

    /// Buffers of the advection kernels (shaders/SmokeAdvectParams.h gives their layouts): the
    /// fluid cells' list with their emitters' rates, the stencil mask, MacCormack's intermediate
    /// fields and per-cell record, and the basis velocity as face pairs.
    const vulkan::DeviceBuffer& fluidCells() const { return mFluidCells; }
    const vulkan::DeviceBuffer& stencilMask() const { return mStencilMask; }
    const vulkan::DeviceBuffer& hat() const { return mHat; }
    const vulkan::DeviceBuffer& record() const { return mRecord; }
    const vulkan::DeviceBuffer& facePairs() const { return mFacePairs; }

    /// Makes the next fields current (SmokeAdvectionKernels::record() calls it).
    void flip() { mCurrent = 1 - mCurrent; }

private:
    MacGrid mBasis;
    int mScale;
    MacGrid mSmoke;
    std::vector<std::uint8_t> mFluid;       ///< the mask as 0 and 1, for setEmitters
    std::vector<std::int64_t> mFluidIndex;  ///< cellIndex of each fluid cell, list order
    std::uint32_t mFluidCount = 0;
    std::array<vulkan::DeviceBuffer, 2> mFields;
    vulkan::DeviceBuffer mTemperature;
    vulkan::DeviceBuffer mMask;
    vulkan::DeviceBuffer mFluidCells;
    vulkan::DeviceBuffer mStencilMask;
    vulkan::DeviceBuffer mHat;
    vulkan::DeviceBuffer mRecord;
    vulkan::DeviceBuffer mFacePairs;
    std::uint32_t mEmitterCount = 0;
    int mCurrent = 0;
};

}  // namespace modeflow::device
