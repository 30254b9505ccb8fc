#pragma once
/// @file SmokeState.h
/// The smoke on the device: density and temperature as float32 ping-pong buffers on the smoke
/// grid (basisGrid.refined(scale)), MacCormack's intermediate fields, the fluid mask and the
/// emitters. SmokeAdvectionKernels::record() reads the current fields, writes the others and
/// flips: after recording, current() names what the step will have written, so several steps
/// can be recorded into one submission with no host round trip. Read the fields back only after
/// the submission's fence (CommandSequence::submitAndWait()).

#include <array>
#include <cstdint>
#include <span>

#include "engine/field/MacGrid.h"
#include "engine/field/SmokeEmitter.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {

class VulkanContext;

class SmokeState {
public:
    /// Fields start at 0. `fluidMask`: one entry per smoke cell, non-zero inside Ω.
    /// @throw modeflow::Error when scale < 1, the mask has the wrong size, or a buffer would
    /// exceed the device's storage buffer range.
    SmokeState(const VulkanContext& context, const MacGrid& basisGrid, int scale,
               std::span<const std::uint8_t> fluidMask);

    const MacGrid& basisGrid() const { return mBasis; }
    const MacGrid& smokeGrid() const { return mSmoke; }
    int scale() const { return mScale; }
    std::int64_t cellCount() const { return mSmoke.cellCount(); }

    /// Replaces the current fields (one value per smoke cell each). Between submissions only.
    /// @throw modeflow::Error on a wrong size.
    void upload(std::span<const float> density, std::span<const float> temperature);
    /// Copies the current fields out. After the writing submission's fence only.
    void download(std::span<float> densityOut, std::span<float> temperatureOut) const;

    /// The emitters of the following steps (float32 on the device). Between submissions only.
    /// @throw modeflow::Error when there are more than maxSmokeEmitters.
    void setEmitters(std::span<const SmokeEmitter> emitters);
    std::uint32_t emitterCount() const { return mEmitterCount; }

    const DeviceBuffer& density() const { return mDensity[mCurrent]; }
    const DeviceBuffer& temperature() const { return mTemperature[mCurrent]; }
    const DeviceBuffer& nextDensity() const { return mDensity[1 - mCurrent]; }
    const DeviceBuffer& nextTemperature() const { return mTemperature[1 - mCurrent]; }
    const DeviceBuffer& densityHat() const { return mDensityHat; }
    const DeviceBuffer& temperatureHat() const { return mTemperatureHat; }
    const DeviceBuffer& mask() const { return mMask; }
    const DeviceBuffer& emitters() const { return mEmitters; }

    /// Makes the next fields current (SmokeAdvectionKernels::record() calls it).
    void flip() { mCurrent = 1 - mCurrent; }

private:
    MacGrid mBasis;
    int mScale;
    MacGrid mSmoke;
    std::array<DeviceBuffer, 2> mDensity;
    std::array<DeviceBuffer, 2> mTemperature;
    DeviceBuffer mDensityHat;
    DeviceBuffer mTemperatureHat;
    DeviceBuffer mMask;
    DeviceBuffer mEmitters;
    std::uint32_t mEmitterCount = 0;
    int mCurrent = 0;
};

}  // namespace modeflow::vulkan
