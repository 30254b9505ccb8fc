#pragma once
/// @file ModeBuffer.h
/// The velocity basis on the device, in tiles of each mode (below), for the reconstruction and
/// force projection kernels. Float32, or float16 packed two per 32-bit word
/// (read with unpackHalf2x16, so no 16-bit storage feature is needed; DOFs 2w and 2w+1 share word
/// w, the even one in the low half). Float16 modes are stored divided by their max |value| and
/// the factor kept per mode (scales()): ⋆-orthonormal fluxes of fine 3D grids are ~1e-4, where
/// float16 is already subnormal.
///
/// Layout, for the kernels' fetches (shaders/ModeAccess.glsl says why): each mode is cut into
/// 16-byte vectors (4 float32 or 8 float16 DOFs) and zero-padded to whole tiles of kTileVectors
/// vectors (a padded DOF adds 0 to every sum); a chunk holds tile 0 of each of its modes in mode
/// order, then tile 1 of each, and so on. One tile of one mode is what kTileLanes neighbouring
/// invocations read, vectors kTileRows·lane … kTileRows·lane + kTileRows − 1 of it (one texel
/// each).
///
/// A basis larger than the device's buffer limit (VulkanContext::texelBufferLimit: the kernels read
/// it as texels) is split by whole modes into several buffers (chunks), a multiple of 4 modes each
/// where the limit allows it (the kernels read the modal state four modes at a time); the kernels
/// take one dispatch per chunk.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/core/ModePrecision.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class ModeBuffer {
public:
    /// Invocations that share a tile (lavapipe's SIMD width with AVX2: its batches of
    /// invocations then read one contiguous stream) and the vectors (texels) each reads per mode.
    static constexpr std::uint32_t kTileLanes = 8;
    static constexpr std::uint32_t kTileRows = 2;
    static constexpr std::uint32_t kTileVectors = kTileLanes * kTileRows;

    struct Chunk {
        std::uint32_t firstMode = 0;
        std::uint32_t modeCount = 0;
        vulkan::DeviceBuffer buffer;  ///< modeCount × modeStride() words, tile-major
    };

    /// Uploads `modes` (DOFs × N, one column per mode, e.g. BasisCache::velocity.modes).
    /// @throw modeflow::Error when there are no modes or DOFs, more than 2^32 DOFs, or a single
    /// mode exceeds the buffer limit.
    ModeBuffer(const vulkan::VulkanContext& context, const Eigen::MatrixXd& modes,
               ModePrecision precision = ModePrecision::Float32);

    std::uint32_t dofCount() const { return mDofCount; }
    std::uint32_t modeCount() const { return mModeCount; }
    ModePrecision precision() const { return mPrecision; }
    /// DOFs per 16-byte vector: 4 (float32) or 8 (float16).
    std::uint32_t dofsPerVector() const { return dofsPerVector(mPrecision); }
    /// 16-byte vectors per mode: the DOF count divided by dofsPerVector(), rounded up to whole
    /// tiles.
    std::uint32_t modeVectors() const { return mModeStride / 4; }
    std::uint32_t tileCount() const { return modeVectors() / kTileVectors; }
    /// 32-bit words per mode: 4 × modeVectors().
    std::uint32_t modeStride() const { return mModeStride; }
    const std::vector<Chunk>& chunks() const { return mChunks; }
    /// One float per mode, padded with zeros to a multiple of 4 (kernels read them four at a
    /// time): the factor the stored values are multiplied by (1 for float32).
    const vulkan::DeviceBuffer& scales() const { return mScales; }
    /// N rounded up to a multiple of 4: the floats a modal state buffer holds for the kernels
    /// that read it four at a time (zeros past N; ModalStepper's state buffers are padded so too).
    std::uint32_t paddedModeCount() const { return (mModeCount + 3) / 4 * 4; }

    static std::uint32_t dofsPerVector(ModePrecision precision) {
        return precision == ModePrecision::Float16 ? 8 : 4;
    }

    /// The modes as the device holds them (rounded, scales applied), for tests and error bounds.
    static Eigen::MatrixXd rounded(const Eigen::MatrixXd& modes, ModePrecision precision);

private:
    std::uint32_t mDofCount = 0;
    std::uint32_t mModeCount = 0;
    ModePrecision mPrecision = ModePrecision::Float32;
    std::uint32_t mModeStride = 0;
    std::vector<Chunk> mChunks;
    vulkan::DeviceBuffer mScales;
};

}  // namespace modeflow::device
