#pragma once
/// @file SmokeState.h
/// The smoke on the device: density and temperature as float32 ping-pong buffers on the smoke
/// grid (basisGrid.refined(scale)), the fluid mask, the emitters, and what the advection kernels
/// read and write on the way (layouts: shaders/SmokeAdvectParams.h; why: shaders/SmokeAdvect.glsl).
/// With fire, a second pair of fields rides along: (fuel, flame), carried by the same kernels as
/// (density, temperature), its own list of the emitters' (fuel) rates, and the flame alone as the
/// temperature is (SmokePair::Fuel). The kernels carry the flame as they carry the fuel; the
/// burn (shaders/fire_burn.comp), the step's last stage, writes every cell's flame anew.
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
#include "engine/core/SceneSpec.h"
#include "engine/simulation/OutsideAir.h"
#include "engine/simulation/SmokeEmitter.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeState;

/// The grids' shape in a smoke kernel's push constants (SmokeAdvectParams, SmokeFluxParams):
/// the smoke and basis cells per axis, the scale, the basis grid's face offsets, and its
/// boundary bits with the state's inflow sides.
template <typename Params>
void setGridParams(Params& p, const SmokeState& state);

/// The pairs of fields a step carries: (density, temperature) always, (fuel, flame) with fire.
enum class SmokePair { Smoke = 0, Fuel = 1 };

class SmokeState {
public:
    /// Fields start at 0. `fluidMask`: one entry per smoke cell, non-zero inside Ω. `fire`: the
    /// state carries fuel and flame too.
    /// @throw modeflow::Error when scale < 1, the mask has the wrong size, the smoke grid has more
    /// than 65535 cells along x or y, or a buffer would exceed the device's texel or storage
    /// buffer limit.
    SmokeState(const vulkan::VulkanContext& context, const MacGrid& basisGrid, int scale,
               std::span<const std::uint8_t> fluidMask, bool fire = false);

    /// The wind blowing through the box ([wind]), as reference::SmokeAdvection::setWind: the
    /// basis grid's sides it crosses open (MacGrid::flowThrough), its upstream sides inflows of
    /// its air (inflowBits, ghosts). Before setInflows; between submissions only.
    void setWind(const WindSpec& wind);
    /// The `[[inflow]]` patches letting air in from now on, as the reference's setInflows.
    /// Between submissions only.
    void setInflows(std::span<const InflowPatch> active);
    /// The inflow sides as SmokeAdvectParams::boundary's SMOKE_INFLOW_* bits, and what the air
    /// coming in across them carries: OutsideAir's ghosts as RGBA32 texels (density,
    /// temperature, fuel, 0).
    std::uint32_t inflowBits() const;
    const OutsideAir& outsideAir() const { return mOutside; }
    const vulkan::DeviceBuffer& ghosts() const { return mGhosts; }

    const MacGrid& basisGrid() const { return mBasis; }
    const MacGrid& smokeGrid() const { return mSmoke; }
    int scale() const { return mScale; }
    std::int64_t cellCount() const { return mSmoke.cellCount(); }
    /// Cells inside Ω: the advection's invocations.
    std::uint32_t fluidCellCount() const { return mFluidCount; }

    bool fire() const { return mPairs.size() == 2; }
    /// The pairs carried: Smoke, then Fuel with fire.
    int pairCount() const { return int(mPairs.size()); }

    /// Replaces the current fields of `pair` (one value per smoke cell each; cells outside Ω
    /// become 0). Between submissions only.
    /// @throw modeflow::Error on a wrong size, or for the fuel of a state without fire.
    void upload(std::span<const float> first, std::span<const float> second,
                SmokePair pair = SmokePair::Smoke);
    /// Copies the current fields of `pair` out. After the writing submission's fence only.
    void download(std::span<float> firstOut, std::span<float> secondOut,
                  SmokePair pair = SmokePair::Smoke) const;

    /// The emitters of the following steps: their rates (fuel too with fire), summed per fluid
    /// cell in double precision with the CPU reference's inside test (applyEmitters), go to the
    /// device as float32. Between submissions only.
    /// @throw modeflow::Error when there are more than maxSmokeEmitters.
    void setEmitters(std::span<const SmokeEmitter> emitters);
    std::uint32_t emitterCount() const { return mEmitterCount; }

    /// A pair's two fields interleaved, e.g. (density, temperature) per cell: now and next.
    const vulkan::DeviceBuffer& fields(SmokePair pair = SmokePair::Smoke) const {
        return at(pair).fields[mCurrent];
    }
    const vulkan::DeviceBuffer& nextFields(SmokePair pair = SmokePair::Smoke) const {
        return at(pair).fields[1 - mCurrent];
    }
    /// A pair's current second field alone, one float per cell: the temperature (e.g. for
    /// ForceFieldKernel), or the flame.
    const vulkan::DeviceBuffer& second(SmokePair pair) const { return at(pair).second; }
    const vulkan::DeviceBuffer& temperature() const { return second(SmokePair::Smoke); }
    /// The fluid mask, one byte per cell packed four to a 32-bit word.
    const vulkan::DeviceBuffer& mask() const { return mMask; }

    /// Buffers of the advection kernels (shaders/SmokeAdvectParams.h gives their layouts): the
    /// fluid cells' list with the emitters' rates of a pair, the stencil mask, MacCormack's
    /// intermediate fields and per-cell record (shared by the pairs, carried one after the
    /// other), and the basis velocity as face pairs.
    const vulkan::DeviceBuffer& fluidCells(SmokePair pair = SmokePair::Smoke) const {
        return at(pair).cells;
    }
    const vulkan::DeviceBuffer& stencilMask() const { return mStencilMask; }
    const vulkan::DeviceBuffer& hat() const { return mHat; }
    const vulkan::DeviceBuffer& record() const { return mRecord; }
    const vulkan::DeviceBuffer& facePairs() const { return mFacePairs; }

    /// Makes the next fields current (SmokeAdvectionKernels::record() calls it).
    void flip() { mCurrent = 1 - mCurrent; }
    /// Which of each pair's two fields is current (0 or 1): a step recorded once reads and
    /// writes the same ones each time it is submitted.
    int parity() const { return mCurrent; }

private:
    /// One pair: its fields now and next, its second field alone, and the fluid cell list with
    /// the emitters' rates of its two fields.
    struct Pair {
        std::array<vulkan::DeviceBuffer, 2> fields;
        vulkan::DeviceBuffer second;
        vulkan::DeviceBuffer cells;
    };
    /// @throw modeflow::Error for the fuel of a state without fire.
    const Pair& at(SmokePair pair) const;
    Pair& at(SmokePair pair);

    MacGrid mBasis;
    int mScale;
    MacGrid mSmoke;
    std::vector<std::uint8_t> mFluid;       ///< the mask as 0 and 1, for setEmitters
    std::vector<std::int64_t> mFluidIndex;  ///< cellIndex of each fluid cell, list order
    std::uint32_t mFluidCount = 0;
    OutsideAir mOutside;  ///< open sides, a wind's upstream ones, and what comes in there
    std::vector<Pair> mPairs;
    vulkan::DeviceBuffer mMask;
    vulkan::DeviceBuffer mStencilMask;
    vulkan::DeviceBuffer mHat;
    vulkan::DeviceBuffer mRecord;
    vulkan::DeviceBuffer mFacePairs;
    vulkan::DeviceBuffer mGhosts;
    std::uint32_t mEmitterCount = 0;
    int mCurrent = 0;
};

template <typename Params>
void setGridParams(Params& p, const SmokeState& state) {
    const MacGrid& basis = state.basisGrid();
    const MacGrid& smoke = state.smokeGrid();
    p.cellsX = std::uint32_t(smoke.cells[0]);
    p.cellsY = std::uint32_t(smoke.cells[1]);
    p.cellsZ = std::uint32_t(smoke.cells[2]);
    p.basisX = std::uint32_t(basis.cells[0]);
    p.basisY = std::uint32_t(basis.cells[1]);
    p.basisZ = std::uint32_t(basis.cells[2]);
    p.scale = std::uint32_t(state.scale());
    p.faceOffsetY = std::uint32_t(basis.faceOffset(1));
    p.faceOffsetZ = std::uint32_t(basis.faceOffset(2));
    p.boundary = basis.boundaryBits() | state.inflowBits();
}

}  // namespace modeflow::device
