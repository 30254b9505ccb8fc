#include "engine/device/SmokeState.h"

#include <algorithm>
#include <array>
#include <bit>
#include <string>
#include <utility>

#include "engine/core/Error.h"
#include "engine/simulation/WindTransport.h"
#include "engine/vulkan/VulkanContext.h"
#include "shaders/SmokeAdvectParams.h"

namespace modeflow::device {
namespace {

/// The mask as 0 and 1, after checking its size and the grid's extent.
std::vector<std::uint8_t> fluidFlags(const MacGrid& smoke, std::span<const std::uint8_t> mask) {
    if (mask.size() != std::size_t(smoke.cellCount()))
        throw Error("smoke state: the fluid mask has " + std::to_string(mask.size()) +
                    " entries, the smoke grid " + std::to_string(smoke.cellCount()) + " cells");
    if (smoke.cells[0] > int(SMOKE_CELL_AXIS_LIMIT) || smoke.cells[1] > int(SMOKE_CELL_AXIS_LIMIT))
        throw Error("smoke state: the smoke grid has " + std::to_string(smoke.cells[0]) + " x " +
                    std::to_string(smoke.cells[1]) +
                    " cells along x and y, the device kernels take at most " +
                    std::to_string(SMOKE_CELL_AXIS_LIMIT) + " along each");
    std::vector<std::uint8_t> flags(mask.size());
    for (std::size_t c = 0; c < mask.size(); ++c) flags[c] = mask[c] != 0;
    return flags;
}

std::vector<std::int64_t> fluidIndices(const std::vector<std::uint8_t>& fluid) {
    std::vector<std::int64_t> indices;
    for (std::size_t c = 0; c < fluid.size(); ++c)
        if (fluid[c]) indices.push_back(std::int64_t(c));
    return indices;
}

/// `values` padded with zeros to whole texels, at least one: the kernels read these buffers as
/// texels (DeviceBuffer::texelView), which cover whole texels only.
template <typename T>
vulkan::DeviceBuffer texelBuffer(const vulkan::VulkanContext& context, std::vector<T> values,
                                 const std::string& name) {
    static_assert(vulkan::DeviceBuffer::kTexelBytes % sizeof(T) == 0);
    constexpr std::size_t perTexel = vulkan::DeviceBuffer::kTexelBytes / sizeof(T);
    values.resize(std::max<std::size_t>((values.size() + perTexel - 1) / perTexel, 1) * perTexel,
                  T{});
    const std::size_t bytes = values.size() * sizeof(T);
    if (bytes > context.texelBufferLimit())
        throw Error("smoke state: " + name + " would take " + std::to_string(bytes) +
                    " bytes, more than the " + std::to_string(context.texelBufferLimit()) +
                    "-byte texel buffer limit of " + context.deviceName());
    return vulkan::DeviceBuffer::fromValues<T>(context, values, name);
}

/// A buffer of `bytes` (a multiple of 4) holding zeros, padded to whole texels.
vulkan::DeviceBuffer zeroBuffer(const vulkan::VulkanContext& context, std::size_t bytes,
                                const std::string& name) {
    return texelBuffer(context, std::vector<std::uint32_t>(bytes / 4, 0), name);
}

/// Per cell: bit cx + 2 cy + 4 cz set when cell (x + cx, y + cy, z + cz) exists and is fluid
/// (across the seam along a periodic axis).
std::vector<std::uint8_t> stencilFlags(const MacGrid& smoke,
                                       const std::vector<std::uint8_t>& fluid) {
    std::vector<std::uint8_t> bits(fluid.size(), 0);
    const auto fluidAt = [&](int x, int y, int z) {
        x = smoke.wrap(0, x);
        y = smoke.wrap(1, y);
        z = smoke.wrap(2, z);
        return x < smoke.cells[0] && y < smoke.cells[1] && z < smoke.cells[2] &&
               fluid[smoke.cellIndex(x, y, z)];
    };
    for (int z = 0; z < smoke.cells[2]; ++z)
        for (int y = 0; y < smoke.cells[1]; ++y)
            for (int x = 0; x < smoke.cells[0]; ++x) {
                std::uint8_t b = 0;
                for (int corner = 0; corner < 8; ++corner)
                    if (fluidAt(x + (corner & 1), y + (corner >> 1 & 1), z + (corner >> 2)))
                        b = std::uint8_t(b | (1u << corner));
                bits[smoke.cellIndex(x, y, z)] = b;
            }
    return bits;
}

/// The fluid cell list, one texel per entry: x | y << 16, z, and the emitters' density and
/// temperature rates (`rates`, two per entry, empty: none).
std::vector<std::uint32_t> cellList(const MacGrid& smoke, const std::vector<std::int64_t>& indices,
                                    std::span<const float> rates) {
    std::vector<std::uint32_t> words(std::max<std::size_t>(indices.size(), 1) * 4,
                                     0);  // never empty
    for (std::size_t e = 0; e < indices.size(); ++e) {
        const std::int64_t c = indices[e];
        const std::int64_t row = c / smoke.cells[0];
        const auto x = std::uint32_t(c % smoke.cells[0]), y = std::uint32_t(row % smoke.cells[1]),
                   z = std::uint32_t(row / smoke.cells[1]);
        words[4 * e] = x | y << 16;
        words[4 * e + 1] = z;
        if (!rates.empty()) {
            words[4 * e + 2] = std::bit_cast<std::uint32_t>(rates[2 * e]);
            words[4 * e + 3] = std::bit_cast<std::uint32_t>(rates[2 * e + 1]);
        }
    }
    return words;
}

}  // namespace

std::uint32_t SmokeState::inflowBits() const {
    std::uint32_t bits = 0;
    for (std::uint32_t a = 0; a < 3; ++a) {
        if (mOutside.sides()[2 * a]) bits |= 1u << (SMOKE_INFLOW_LOW + a);
        if (mOutside.sides()[2 * a + 1]) bits |= 1u << (SMOKE_INFLOW_HIGH + a);
    }
    return bits;
}

void SmokeState::setWind(const WindSpec& wind) {
    mBasis = withWindThrough(mBasis, wind.velocity);
    mOutside = OutsideAir(mSmoke, inflowSides(mSmoke, wind.velocity),
                          {wind.density, wind.temperature, 0.0});  // the wind brings no fuel
    mGhosts.upload<float>(mOutside.texels());
}

void SmokeState::setInflows(std::span<const InflowPatch> active) {
    mOutside.setInflows(active);
    mGhosts.upload<float>(mOutside.texels());
}

SmokeState::SmokeState(const vulkan::VulkanContext& context, const MacGrid& basisGrid, int scale,
                       std::span<const std::uint8_t> fluidMask, bool fire)
    : mBasis(basisGrid),
      mScale(scale),
      mSmoke(basisGrid.refined(scale)),
      mFluid(fluidFlags(mSmoke, fluidMask)),
      mFluidIndex(fluidIndices(mFluid)),
      mFluidCount(std::uint32_t(mFluidIndex.size())),
      mOutside(mSmoke, mSmoke.open),  // open sides take in clean air
      mMask(texelBuffer(context, mFluid, "smoke fluid mask")),
      mStencilMask(texelBuffer(context, stencilFlags(mSmoke, mFluid), "smoke stencil mask")),
      mHat(zeroBuffer(context, std::size_t(mSmoke.cellCount()) * 8, "MacCormack fields")),
      mRecord(zeroBuffer(context, std::size_t(mFluidCount) * SMOKE_RECORD_WORDS * 8,
                         "MacCormack record")),
      mFacePairs(
          zeroBuffer(context, std::size_t(mBasis.faceTotal() + 3) / 4 * 32, "smoke face pairs")),
      mGhosts(texelBuffer(context, mOutside.texels(), "smoke ghosts")) {
    // Each pair's fields 0, its emitters' rates none yet.
    const auto cells = std::size_t(mSmoke.cellCount());
    const auto addPair = [&](const std::string& name) {
        mPairs.push_back(
            {{zeroBuffer(context, cells * 8, name + " fields 0"),
              zeroBuffer(context, cells * 8, name + " fields 1")},
             zeroBuffer(context, cells * 4, name + " second field"),
             texelBuffer(context, cellList(mSmoke, mFluidIndex, {}), name + " fluid cells")});
    };
    addPair("smoke");
    if (fire) addPair("fuel");
}

const SmokeState::Pair& SmokeState::at(SmokePair pair) const {
    const auto p = std::size_t(pair);
    if (p >= mPairs.size())
        throw Error("smoke state: fuel and flame asked of a state without fire");
    return mPairs[p];
}

SmokeState::Pair& SmokeState::at(SmokePair pair) {
    return const_cast<Pair&>(std::as_const(*this).at(pair));
}

void SmokeState::upload(std::span<const float> first, std::span<const float> second,
                        SmokePair pair) {
    if (first.size() != std::size_t(cellCount()) || second.size() != std::size_t(cellCount()))
        throw Error(
            "smoke state upload: " +
            std::string(pair == SmokePair::Smoke ? "density and temperature" : "fuel and flame") +
            " need " + std::to_string(cellCount()) + " values each, got " +
            std::to_string(first.size()) + " and " + std::to_string(second.size()));
    Pair& target = at(pair);
    std::vector<float> pairs(2 * first.size(), 0.0f), alone(second.size(), 0.0f);
    for (const std::int64_t c : mFluidIndex) {
        pairs[2 * c] = first[c];
        pairs[2 * c + 1] = alone[c] = second[c];
    }
    target.fields[mCurrent].upload<float>(pairs);
    target.second.upload<float>(alone);
}

void SmokeState::download(std::span<float> firstOut, std::span<float> secondOut,
                          SmokePair pair) const {
    if (firstOut.size() != std::size_t(cellCount()) || secondOut.size() != std::size_t(cellCount()))
        throw Error("smoke state download: the two fields need room for " +
                    std::to_string(cellCount()) + " values each");
    std::vector<float> pairs(2 * firstOut.size());
    fields(pair).download<float>(pairs);
    for (std::size_t c = 0; c < firstOut.size(); ++c) {
        firstOut[c] = pairs[2 * c];
        secondOut[c] = pairs[2 * c + 1];
    }
}

void SmokeState::setEmitters(std::span<const SmokeEmitter> emitters) {
    if (emitters.size() > std::size_t(maxSmokeEmitters))
        throw Error("smoke: " + std::to_string(emitters.size()) +
                    " emitters, the device step takes at most " + std::to_string(maxSmokeEmitters));
    // The rates per unit time: the reference's emitters over a step of 1.
    std::vector<double> density(mFluid.size(), 0.0), temperature(mFluid.size(), 0.0),
        fuel(fire() ? mFluid.size() : 0, 0.0);
    applyEmitters(mSmoke, mFluid, emitters, 1.0, density, temperature, fuel);
    std::vector<float> rates(2 * mFluidIndex.size()), fuelRates(fire() ? rates.size() : 0, 0.0f);
    for (std::size_t e = 0; e < mFluidIndex.size(); ++e) {
        const auto c = std::size_t(mFluidIndex[e]);
        rates[2 * e] = float(density[c]);
        rates[2 * e + 1] = float(temperature[c]);
        if (fire()) fuelRates[2 * e] = float(fuel[c]);  // the flame has no source
    }
    mPairs[0].cells.upload<std::uint32_t>(cellList(mSmoke, mFluidIndex, rates));
    if (fire()) mPairs[1].cells.upload<std::uint32_t>(cellList(mSmoke, mFluidIndex, fuelRates));
    mEmitterCount = std::uint32_t(emitters.size());
}

}  // namespace modeflow::device
