#pragma once
/// @file DeviceHandle.h
/// A move-only owner of one VkDevice child object (buffer, memory, pipeline, …). Every such
/// object is destroyed by a `vkDestroyX(device, handle, allocator)` call of the same shape, so one
/// template covers them all; members declared in dependency order then destroy in the right
/// order by construction.

#include <utility>

#include <vulkan/vulkan.h>

namespace modeflow::vulkan {

template <typename Handle>
class DeviceHandle {
public:
    using Destroy = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);

    DeviceHandle() = default;
    /// Takes ownership of `handle`, which `destroy` releases.
    DeviceHandle(VkDevice device, Handle handle, Destroy destroy)
        : mDevice(device), mHandle(handle), mDestroy(destroy) {}
    ~DeviceHandle() { reset(); }

    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;
    DeviceHandle(DeviceHandle&& other) noexcept
        : mDevice(other.mDevice),
          mHandle(std::exchange(other.mHandle, VK_NULL_HANDLE)),
          mDestroy(other.mDestroy) {}
    DeviceHandle& operator=(DeviceHandle&& other) noexcept {
        if (this != &other) {
            reset();
            mDevice = other.mDevice;
            mHandle = std::exchange(other.mHandle, VK_NULL_HANDLE);
            mDestroy = other.mDestroy;
        }
        return *this;
    }

    Handle get() const { return mHandle; }
    bool isValid() const { return mHandle != VK_NULL_HANDLE; }

    void reset() {
        if (mHandle != VK_NULL_HANDLE)
            mDestroy(mDevice, std::exchange(mHandle, VK_NULL_HANDLE), nullptr);
    }

private:
    VkDevice mDevice = VK_NULL_HANDLE;
    Handle mHandle = VK_NULL_HANDLE;
    Destroy mDestroy = nullptr;
};

}  // namespace modeflow::vulkan
