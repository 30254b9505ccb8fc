#pragma once
/// @file DeviceBuffer.h
/// A storage buffer the kernels read and write. Where the device's memory is the host's (lavapipe,
/// integrated GPUs) the buffer lives in host-visible memory that stays mapped, and upload and
/// download are plain copies. On a discrete GPU it lives in device-local memory, which kernels
/// read at full speed but the host cannot map: upload and download then go through the context's
/// StagingArea, a reused host-visible buffer and a copy command (VulkanContext::usesStaging()).
///
/// A buffer of at least one 16-byte texel within VulkanContext::texelBufferLimit() also has a
/// texel view (RGBA32UI) over its whole texels, so kernels may read it as a uniform texel buffer
/// (`usamplerBuffer`, ComputeKernelSpec::texelBindings): lavapipe fetches texels with vector
/// gathers, about 3× the bandwidth of its storage buffer loads (shaders/TexelAccess.glsl). Bytes
/// past the last whole texel read as zero there. Two more views read it a 64-bit word (RG32UI,
/// wordView) or a 32-bit value (R32UI, floatView) at a time, for kernels whose reads are single
/// words or values (ComputeKernelSpec::wordBindings, floatBindings): a fetch then gathers the
/// components in use only.

#include <cstddef>
#include <span>
#include <string>
#include <type_traits>

#include <vulkan/vulkan.h>

#include "engine/core/Error.h"
#include "engine/vulkan/DeviceHandle.h"

namespace modeflow::vulkan {

class VulkanContext;

class DeviceBuffer {
public:
    enum class Placement {
        Automatic,    ///< device-local on discrete GPUs (staged copies), else mapped
        HostVisible,  ///< always mapped host-visible memory (staging buffers, small readbacks)
    };

    /// A buffer of `bytes` bytes (contents undefined). `name` appears in error messages.
    /// @throw modeflow::Error if `bytes` is 0 or exceeds VulkanContext::storageBufferLimit()
    /// (the message gives both sizes), if no suitable memory type exists, or if a creation call
    /// fails.
    DeviceBuffer(const VulkanContext& context, VkDeviceSize bytes, std::string name = "buffer",
                 Placement placement = Placement::Automatic);

    /// A view of `bytes` bytes of `whole` from byte `offset`: a buffer of its own over the same
    /// memory, so that kernels may bind part of an array (e.g. one half of a modal state) while
    /// others bind all of it. `whole` must outlive the view.
    /// @throw modeflow::Error if the range does not fit in `whole`, `offset` is not a multiple of
    /// 256 bytes (what every device's storage and texel offset alignments allow), or a creation
    /// call fails.
    DeviceBuffer(const DeviceBuffer& whole, VkDeviceSize offset, VkDeviceSize bytes,
                 std::string name);

    /// Offsets DeviceBuffer views must be multiples of.
    static constexpr VkDeviceSize kViewAlignment = 256;

    /// A buffer holding a copy of `values`.
    template <typename T>
    static DeviceBuffer fromValues(const VulkanContext& context, std::span<const T> values,
                                   std::string name = "buffer") {
        DeviceBuffer buffer(context, values.size_bytes(), std::move(name));
        buffer.upload(values);
        return buffer;
    }

    /// Bytes per texel of texelView().
    static constexpr VkDeviceSize kTexelBytes = 16;
    /// Bytes per texel of wordView() and floatView().
    static constexpr VkDeviceSize kWordBytes = 8;
    static constexpr VkDeviceSize kFloatBytes = 4;

    VkBuffer handle() const { return mBuffer.get(); }
    VkDeviceSize bytes() const { return mBytes; }
    const std::string& name() const { return mName; }
    /// The RGBA32UI view over the buffer's whole 16-byte texels, or VK_NULL_HANDLE when it is
    /// smaller than one texel or larger than VulkanContext::texelBufferLimit().
    VkBufferView texelView() const { return mTexelView.get(); }
    /// The RG32UI view over the buffer's whole 8-byte words (one 64-bit word a texel), or
    /// VK_NULL_HANDLE as texelView().
    VkBufferView wordView() const { return mWordView.get(); }
    /// The R32UI view over its 32-bit values (one a texel), or VK_NULL_HANDLE as texelView().
    VkBufferView floatView() const { return mFloatView.get(); }
    /// True when the host reads and writes the memory directly (no staging copy).
    bool isMapped() const { return mMapped != nullptr; }

    /// Copies `values` into the buffer at byte `offset`. Call between submissions only.
    /// @throw modeflow::Error if the range does not fit or a staging copy fails.
    template <typename T>
    void upload(std::span<const T> values, VkDeviceSize offset = 0) {
        static_assert(std::is_trivially_copyable_v<T>);
        write(values.data(), offset, values.size_bytes());
    }

    /// Copies bytes starting at `offset` into `values`. Call after the writing submission's fence.
    /// @throw modeflow::Error if the range does not fit or a staging copy fails.
    template <typename T>
    void download(std::span<T> values, VkDeviceSize offset = 0) const {
        static_assert(std::is_trivially_copyable_v<T>);
        read(values.data(), offset, values.size_bytes());
    }

private:
    /// The buffer object over `bytes`, its usage, and whether it gets a texel view.
    VkBuffer createBuffer(VkDeviceSize bytes);
    void createTexelViews(VkDeviceSize bytes);
    DeviceHandle<VkBufferView> createView(VkFormat format, VkDeviceSize texelBytes,
                                          VkDeviceSize bytes) const;
    void checkRange(const char* what, VkDeviceSize offset, VkDeviceSize bytes) const;
    void write(const void* source, VkDeviceSize offset, VkDeviceSize bytes);
    void read(void* destination, VkDeviceSize offset, VkDeviceSize bytes) const;

    const VulkanContext* mContext = nullptr;
    std::string mName;
    VkDeviceSize mBytes = 0;
    // Memory before buffer: the buffer is destroyed first, then its memory is freed (which unmaps).
    DeviceHandle<VkDeviceMemory> mMemory;  ///< empty in a view: the whole buffer's memory
    VkDeviceMemory mMemoryHandle = VK_NULL_HANDLE;
    DeviceHandle<VkBuffer> mBuffer;
    DeviceHandle<VkBufferView> mTexelView, mWordView, mFloatView;  // destroyed before the buffer
    void* mMapped = nullptr;
};

}  // namespace modeflow::vulkan
