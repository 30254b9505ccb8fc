#include "engine/kernels/SmokeState.h"

#include <string>
#include <vector>

#include "engine/format/Error.h"
#include "shaders/SmokeAdvectParams.h"

namespace modeflow::vulkan {
namespace {

DeviceBuffer fieldBuffer(const VulkanContext& context, const MacGrid& smoke, const std::string& name) {
    DeviceBuffer buffer(context, VkDeviceSize(smoke.cellCount()) * sizeof(float), name);
    buffer.upload<float>(std::vector<float>(std::size_t(smoke.cellCount()), 0.0f));
    return buffer;
}

/// The mask as bytes padded to whole 32-bit words (the shader reads 4 cells a word).
DeviceBuffer maskBuffer(const VulkanContext& context, const MacGrid& smoke, std::span<const std::uint8_t> mask) {
    if (mask.size() != std::size_t(smoke.cellCount()))
        throw Error("smoke state: the fluid mask has " + std::to_string(mask.size()) + " entries, the smoke grid " +
                    std::to_string(smoke.cellCount()) + " cells");
    std::vector<std::uint8_t> bytes((mask.size() + 3) / 4 * 4, 0);
    for (std::size_t c = 0; c < mask.size(); ++c) bytes[c] = mask[c] != 0;
    return DeviceBuffer::fromValues<std::uint8_t>(context, bytes, "smoke fluid mask");
}

shaders::SmokeEmitterData toDevice(const SmokeEmitter& e) {
    return {float(e.centre[0]), float(e.centre[1]), float(e.centre[2]), float(e.radius),
            float(e.min[0]),    float(e.min[1]),    float(e.min[2]),    float(e.densityRate),
            float(e.max[0]),    float(e.max[1]),    float(e.max[2]),    float(e.temperatureRate),
            e.shape == EmitterShape::Box ? SMOKE_EMITTER_BOX : SMOKE_EMITTER_BALL, 0, 0, 0};
}

}  // namespace

SmokeState::SmokeState(const VulkanContext& context, const MacGrid& basisGrid, int scale,
                       std::span<const std::uint8_t> fluidMask)
    : mBasis(basisGrid),
      mScale(scale),
      mSmoke(basisGrid.refined(scale)),
      mDensity{fieldBuffer(context, mSmoke, "smoke density 0"), fieldBuffer(context, mSmoke, "smoke density 1")},
      mTemperature{fieldBuffer(context, mSmoke, "smoke temperature 0"),
                   fieldBuffer(context, mSmoke, "smoke temperature 1")},
      mDensityHat(fieldBuffer(context, mSmoke, "MacCormack density")),
      mTemperatureHat(fieldBuffer(context, mSmoke, "MacCormack temperature")),
      mMask(maskBuffer(context, mSmoke, fluidMask)),
      mEmitters(context, maxSmokeEmitters * sizeof(shaders::SmokeEmitterData), "smoke emitters") {}

void SmokeState::upload(std::span<const float> density, std::span<const float> temperature) {
    if (density.size() != std::size_t(cellCount()) || temperature.size() != std::size_t(cellCount()))
        throw Error("smoke state upload: density and temperature need " + std::to_string(cellCount()) +
                    " values each, got " + std::to_string(density.size()) + " and " +
                    std::to_string(temperature.size()));
    mDensity[mCurrent].upload(density);
    mTemperature[mCurrent].upload(temperature);
}

void SmokeState::download(std::span<float> densityOut, std::span<float> temperatureOut) const {
    if (densityOut.size() != std::size_t(cellCount()) || temperatureOut.size() != std::size_t(cellCount()))
        throw Error("smoke state download: density and temperature need room for " + std::to_string(cellCount()) +
                    " values each");
    density().download(densityOut);
    temperature().download(temperatureOut);
}

void SmokeState::setEmitters(std::span<const SmokeEmitter> emitters) {
    if (emitters.size() > std::size_t(maxSmokeEmitters))
        throw Error("smoke: " + std::to_string(emitters.size()) + " emitters, the device step takes at most " +
                    std::to_string(maxSmokeEmitters));
    std::vector<shaders::SmokeEmitterData> data;
    for (const SmokeEmitter& e : emitters) data.push_back(toDevice(e));
    mEmitters.upload<shaders::SmokeEmitterData>(data);
    mEmitterCount = std::uint32_t(emitters.size());
}

}  // namespace modeflow::vulkan
