#pragma once
/// @file StagingArea.h
/// The host-visible buffer, command pool and fence through which DeviceBuffer copies to and from
/// device-local memory (discrete GPUs), made once per context and reused: a run reads its fields
/// back every frame and the modal step's status every step, and allocating pinned host memory,
/// a pool and a fence for each copy cost the H100 more than the copies. Transfers larger than
/// kChunkBytes go through it in pieces, so a basis of gigabytes needs no staging copy of its size.

#include <memory>

#include <vulkan/vulkan.h>

#include "engine/vulkan/DeviceHandle.h"
#include "engine/vulkan/SyncObjects.h"

namespace modeflow::vulkan {

class DeviceBuffer;
class VulkanContext;

class StagingArea {
public:
    /// The most bytes the staging buffer grows to (less where the device's storage buffers are
    /// smaller: a staging buffer is a DeviceBuffer too).
    static constexpr VkDeviceSize kChunkBytes = VkDeviceSize(64) << 20;

    explicit StagingArea(const VulkanContext& context);
    ~StagingArea();
    StagingArea(const StagingArea&) = delete;
    StagingArea& operator=(const StagingArea&) = delete;

    /// Copies `bytes` from `source` into `target` at `offset`, waiting until the device has them.
    /// @throw modeflow::Error naming the call that failed.
    void upload(const DeviceBuffer& target, VkDeviceSize offset, const void* source,
                VkDeviceSize bytes);
    /// Copies `bytes` of `source` from `offset` into `destination`.
    /// @throw modeflow::Error naming the call that failed.
    void download(const DeviceBuffer& source, VkDeviceSize offset, void* destination,
                  VkDeviceSize bytes);

private:
    VkDeviceSize chunkBytes() const;
    /// The staging buffer, grown (up to kChunkBytes) to hold `bytes`.
    DeviceBuffer& buffer(VkDeviceSize bytes);
    /// One copy between the staging buffer's first `bytes` and `device` at `offset`.
    void copy(const DeviceBuffer& device, VkDeviceSize offset, VkDeviceSize bytes, bool toDevice);

    const VulkanContext& mContext;
    std::unique_ptr<DeviceBuffer> mBuffer;
    CommandPool mPool;
    DeviceHandle<VkFence> mFence;
};

}  // namespace modeflow::vulkan
