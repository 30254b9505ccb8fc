#pragma once
/// @file ComputeKernel.h
/// One compute pipeline built from embedded SPIR-V (Kompute's Algorithm): a descriptor set
/// layout of N buffers (bindings 0…N−1 of set 0: storage buffers, or uniform texel buffers of
/// 16-byte RGBA32UI texels for the read-only streams named in texelBindings), a push-constant
/// block, the workgroup size as specialization constant 0 and optional further uint constants 1…k
/// (fixed at pipeline creation, so a shader's branches and loop counts on them fold away: lavapipe
/// executes both sides of a runtime branch). Shaders declare `layout(local_size_x = 64,
/// local_size_x_id = 0) in;` so the size written there is also the default (shaders/README.md).
/// Buffers are bound by push descriptors at record time, so recording needs no descriptor pool and
/// a kernel can be recorded any number of times.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/vulkan/DeviceHandle.h"

namespace modeflow::vulkan {

class DeviceBuffer;
class VulkanContext;

struct ComputeKernelSpec {
    std::string name;                           ///< for error messages
    std::span<const std::uint32_t> spirv;       ///< SPIR-V words (a glslangValidator --vn array)
    std::uint32_t bufferCount = 0;              ///< buffers at bindings 0…N−1
    std::uint32_t pushConstantBytes = 0;        ///< size of the push-constant block (multiple of 4)
    std::uint32_t workgroupSize = 64;           ///< local_size_x, specialization constant 0
    std::vector<std::uint32_t> constants = {};  ///< specialization constants 1…k, in order
    /// The bindings a shader reads as `usamplerBuffer` (DeviceBuffer::texelView), the rest being
    /// storage buffers. For read-only streams: lavapipe gathers texels with vector loads.
    std::vector<std::uint32_t> texelBindings = {};
    /// The bindings a shader reads as `usamplerBuffer` of 64-bit words (DeviceBuffer::wordView,
    /// RG32UI): where the reads are single words, a fetch gathers two components, not four.
    std::vector<std::uint32_t> wordBindings = {};
    /// The bindings read as `usamplerBuffer` of 32-bit values (DeviceBuffer::floatView, R32UI):
    /// where values are read one at a time.
    std::vector<std::uint32_t> floatBindings = {};
};

class ComputeKernel {
public:
    /// @throw modeflow::Error if the workgroup size exceeds the device's limits, the push
    /// constants exceed maxPushConstantsSize, or a creation call fails (with its VkResult).
    ComputeKernel(const VulkanContext& context, const ComputeKernelSpec& spec);

    /// Binds the pipeline and `buffers` (exactly bufferCount, in binding order; those at texel
    /// bindings through their texel views), pushes
    /// `pushConstants` (exactly pushConstantBytes) and dispatches `groupCount` workgroups along x.
    /// Records only: barriers and submission belong to CommandSequence.
    /// @throw modeflow::Error on a wrong buffer count, push size, a texel binding given a buffer
    /// without a texel view, or a group count over the limit.
    void record(VkCommandBuffer commandBuffer, std::span<const DeviceBuffer* const> buffers,
                std::span<const std::byte> pushConstants, std::uint32_t groupCount) const;

    /// record() with a push-constant struct (e.g. a shaders/*Params.h struct).
    template <typename Params>
    void record(VkCommandBuffer commandBuffer, std::span<const DeviceBuffer* const> buffers,
                const Params& params, std::uint32_t groupCount) const {
        record(commandBuffer, buffers, std::as_bytes(std::span(&params, 1)), groupCount);
    }

    /// record() with the group counts read by the device from `arguments` at byte `offset`
    /// (a VkDispatchIndirectCommand, e.g. written by an earlier kernel: a count of 0 skips the
    /// dispatch, which is how iterations stop on the device without a host round trip).
    /// @throw modeflow::Error on a wrong buffer count or push size, or arguments out of range.
    void recordIndirect(VkCommandBuffer commandBuffer, std::span<const DeviceBuffer* const> buffers,
                        std::span<const std::byte> pushConstants, const DeviceBuffer& arguments,
                        VkDeviceSize offset) const;

    const std::string& name() const { return mSpec.name; }
    std::uint32_t workgroupSize() const { return mSpec.workgroupSize; }

private:
    /// The texel view's bytes at `binding` (16, 8 or 4), 0 for a storage buffer.
    VkDeviceSize texelBytes(std::uint32_t binding) const { return mTexelBytes[binding]; }
    /// Binds the pipeline and buffers and pushes the constants, after checking their counts.
    void bind(VkCommandBuffer commandBuffer, std::span<const DeviceBuffer* const> buffers,
              std::span<const std::byte> pushConstants) const;

    const VulkanContext& mContext;
    ComputeKernelSpec mSpec;
    std::vector<VkDeviceSize> mTexelBytes;  ///< per binding, from the spec's lists
    // Dependency order: the pipeline needs its layout, the layout needs the set layout.
    DeviceHandle<VkDescriptorSetLayout> mSetLayout;
    DeviceHandle<VkPipelineLayout> mPipelineLayout;
    DeviceHandle<VkShaderModule> mShader;
    DeviceHandle<VkPipeline> mPipeline;
};

}  // namespace modeflow::vulkan
