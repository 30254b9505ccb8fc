#pragma once
/// @file ModeBuffer.h
/// The velocity basis on the device, mode-major (mode i's DOF values contiguous, so the
/// invocations of one DOF each read neighbouring words of a mode), for the reconstruction and
/// force projection kernels. Float32, or float16 packed two per 32-bit word (read with
/// unpackHalf2x16, so no 16-bit storage feature is needed; DOFs 2w and 2w+1 share word w, the
/// even one in the low half). Float16 modes are stored divided by their max |value| and the
/// factor kept per mode (scales()): ⋆-orthonormal fluxes of fine 3D grids are ~1e-4, where
/// float16 is already subnormal.
///
/// A basis larger than the device's storage buffer limit is split by whole modes into several
/// buffers (chunks); the kernels take one dispatch per chunk.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {

class VulkanContext;

enum class ModePrecision { Float32, Float16 };

class ModeBuffer {
public:
    struct Chunk {
        std::uint32_t firstMode = 0;
        std::uint32_t modeCount = 0;
        DeviceBuffer buffer;  ///< modeCount × modeStride() words
    };

    /// Uploads `modes` (DOFs × N, one column per mode, e.g. BasisCache::velocity.modes).
    /// @throw modeflow::Error when there are no modes or DOFs, more than 2^32 DOFs, or a single
    /// mode exceeds the storage buffer limit.
    ModeBuffer(const VulkanContext& context, const Eigen::MatrixXd& modes,
               ModePrecision precision = ModePrecision::Float32);

    std::uint32_t dofCount() const { return mDofCount; }
    std::uint32_t modeCount() const { return mModeCount; }
    ModePrecision precision() const { return mPrecision; }
    /// 32-bit words per mode: the DOF count, or half of it rounded up for float16.
    std::uint32_t modeStride() const { return mModeStride; }
    const std::vector<Chunk>& chunks() const { return mChunks; }
    /// One float per mode, padded with zeros to a multiple of 4 (kernels read them as vec4s):
    /// the factor the stored values are multiplied by (1 for float32).
    const DeviceBuffer& scales() const { return mScales; }
    /// N rounded up to a multiple of 4: the floats a modal state buffer holds for the kernels
    /// that read it as vec4s (zeros past N; ModalStepper's state buffers are padded so too).
    std::uint32_t paddedModeCount() const { return (mModeCount + 3) / 4 * 4; }

    /// The modes as the device holds them (rounded, scales applied), for tests and error bounds.
    static Eigen::MatrixXd rounded(const Eigen::MatrixXd& modes, ModePrecision precision);

private:
    std::uint32_t mDofCount = 0;
    std::uint32_t mModeCount = 0;
    ModePrecision mPrecision = ModePrecision::Float32;
    std::uint32_t mModeStride = 0;
    std::vector<Chunk> mChunks;
    DeviceBuffer mScales;
};

}  // namespace modeflow::vulkan
