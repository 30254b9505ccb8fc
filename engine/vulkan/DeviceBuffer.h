#pragma once
/// @file DeviceBuffer.h
/// A storage buffer the kernels read and write, in host-visible, host-coherent memory that stays
/// mapped, so upload and download are plain copies. On lavapipe (and integrated GPUs) that memory
/// is also device-local; on discrete GPUs it is not, and a staging path (device-local buffer,
/// transfer through a host-visible one) is future work.

#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>

#include <vulkan/vulkan.h>

#include "engine/format/Error.h"
#include "engine/vulkan/DeviceHandle.h"

namespace modeflow::vulkan {

class VulkanContext;

class DeviceBuffer {
public:
    /// A buffer of `bytes` bytes (contents undefined). `name` appears in error messages.
    /// @throw modeflow::Error if `bytes` is 0 or exceeds the device's maxStorageBufferRange (the
    /// message gives both sizes), if no host-visible coherent memory type exists, or if a
    /// creation call fails.
    DeviceBuffer(const VulkanContext& context, VkDeviceSize bytes, std::string name = "buffer");

    /// A buffer holding a copy of `values`.
    template <typename T>
    static DeviceBuffer fromValues(const VulkanContext& context, std::span<const T> values,
                                   std::string name = "buffer") {
        DeviceBuffer buffer(context, values.size_bytes(), std::move(name));
        buffer.upload(values);
        return buffer;
    }

    VkBuffer handle() const { return mBuffer.get(); }
    VkDeviceSize bytes() const { return mBytes; }
    const std::string& name() const { return mName; }

    /// Copies `values` into the buffer at byte `offset`. Call between submissions only.
    /// @throw modeflow::Error if the range does not fit.
    template <typename T>
    void upload(std::span<const T> values, VkDeviceSize offset = 0) {
        static_assert(std::is_trivially_copyable_v<T>);
        checkRange("upload", offset, values.size_bytes());
        std::memcpy(static_cast<std::byte*>(mMapped) + offset, values.data(), values.size_bytes());
    }

    /// Copies bytes starting at `offset` into `values`. Call after the writing submission's fence.
    /// @throw modeflow::Error if the range does not fit.
    template <typename T>
    void download(std::span<T> values, VkDeviceSize offset = 0) const {
        static_assert(std::is_trivially_copyable_v<T>);
        checkRange("download", offset, values.size_bytes());
        std::memcpy(values.data(), static_cast<const std::byte*>(mMapped) + offset, values.size_bytes());
    }

private:
    void checkRange(const char* what, VkDeviceSize offset, VkDeviceSize bytes) const;

    std::string mName;
    VkDeviceSize mBytes = 0;
    // Memory before buffer: the buffer is destroyed first, then its memory is freed (which unmaps).
    DeviceHandle<VkDeviceMemory> mMemory;
    DeviceHandle<VkBuffer> mBuffer;
    void* mMapped = nullptr;
};

}  // namespace modeflow::vulkan
