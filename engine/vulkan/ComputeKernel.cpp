#include "engine/vulkan/ComputeKernel.h"

#include <array>
#include <vector>

#include "engine/core/Error.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {

ComputeKernel::ComputeKernel(const VulkanContext& context, const ComputeKernelSpec& spec)
    : mContext(context), mSpec(spec) {
    const VkDevice device = context.device();
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    if (spec.workgroupSize == 0 || spec.workgroupSize > limits.maxComputeWorkGroupSize[0] ||
        spec.workgroupSize > limits.maxComputeWorkGroupInvocations)
        throw Error("kernel " + spec.name + ": workgroup size " +
                    std::to_string(spec.workgroupSize) + " is outside 1…" +
                    std::to_string(limits.maxComputeWorkGroupInvocations) + " on " +
                    context.deviceName());
    if (spec.pushConstantBytes > limits.maxPushConstantsSize || spec.pushConstantBytes % 4 != 0)
        throw Error("kernel " + spec.name + ": " + std::to_string(spec.pushConstantBytes) +
                    " bytes of push constants (must be a multiple of 4 and at most " +
                    std::to_string(limits.maxPushConstantsSize) + ")");

    struct TexelList {
        const std::vector<std::uint32_t>* bindings;
        const char* kind;
        VkDeviceSize bytes;
    };
    const std::array<TexelList, 3> lists{
        {{&spec.texelBindings, "texel", DeviceBuffer::kTexelBytes},
         {&spec.wordBindings, "word", DeviceBuffer::kWordBytes},
         {&spec.floatBindings, "float", DeviceBuffer::kFloatBytes}}};
    mTexelBytes.assign(spec.bufferCount, 0);
    for (const TexelList& list : lists)
        for (const std::uint32_t b : *list.bindings) {
            if (b >= spec.bufferCount)
                throw Error("kernel " + spec.name + ": " + list.kind + " binding " +
                            std::to_string(b) + " is not among its " +
                            std::to_string(spec.bufferCount) + " bindings");
            if (mTexelBytes[b] != 0)
                throw Error("kernel " + spec.name + ": binding " + std::to_string(b) +
                            " is listed as texels twice");
            mTexelBytes[b] = list.bytes;
        }
    std::vector<VkDescriptorSetLayoutBinding> bindings(spec.bufferCount);
    for (std::uint32_t b = 0; b < spec.bufferCount; ++b) {
        bindings[b].binding = b;
        bindings[b].descriptorType = texelBytes(b) > 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                                       : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings[b].descriptorCount = 1;
        bindings[b].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = spec.bufferCount;
    setInfo.pBindings = bindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout),
          "vkCreateDescriptorSetLayout");
    mSetLayout =
        DeviceHandle<VkDescriptorSetLayout>(device, setLayout, vkDestroyDescriptorSetLayout);

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, spec.pushConstantBytes};
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = spec.pushConstantBytes > 0 ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &pipelineLayout),
          "vkCreatePipelineLayout");
    mPipelineLayout =
        DeviceHandle<VkPipelineLayout>(device, pipelineLayout, vkDestroyPipelineLayout);

    VkShaderModuleCreateInfo shaderInfo{};
    shaderInfo.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    shaderInfo.codeSize = spec.spirv.size_bytes();
    shaderInfo.pCode = spec.spirv.data();
    VkShaderModule shader = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &shaderInfo, nullptr, &shader), "vkCreateShaderModule");
    mShader = DeviceHandle<VkShaderModule>(device, shader, vkDestroyShaderModule);

    // Constant i (0: the workgroup size) is the i-th uint of `values`.
    std::vector<std::uint32_t> values{spec.workgroupSize};
    values.insert(values.end(), spec.constants.begin(), spec.constants.end());
    std::vector<VkSpecializationMapEntry> entries(values.size());
    for (std::uint32_t i = 0; i < entries.size(); ++i)
        entries[i] = {i, i * std::uint32_t(sizeof(std::uint32_t)), sizeof(std::uint32_t)};
    const VkSpecializationInfo specialization{std::uint32_t(entries.size()), entries.data(),
                                              values.size() * sizeof(std::uint32_t), values.data()};
    VkComputePipelineCreateInfo pipelineInfo{};
    pipelineInfo.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = shader;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.stage.pSpecializationInfo = &specialization;
    pipelineInfo.layout = pipelineLayout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline),
          "vkCreateComputePipelines");
    mPipeline = DeviceHandle<VkPipeline>(device, pipeline, vkDestroyPipeline);
}

void ComputeKernel::bind(VkCommandBuffer commandBuffer,
                         std::span<const DeviceBuffer* const> buffers,
                         std::span<const std::byte> pushConstants) const {
    if (buffers.size() != mSpec.bufferCount)
        throw Error("kernel " + mSpec.name + ": " + std::to_string(buffers.size()) +
                    " buffers given, " + std::to_string(mSpec.bufferCount) + " expected");
    if (pushConstants.size() != mSpec.pushConstantBytes)
        throw Error("kernel " + mSpec.name + ": " + std::to_string(pushConstants.size()) +
                    " bytes of push constants given, " + std::to_string(mSpec.pushConstantBytes) +
                    " expected");

    std::vector<VkDescriptorBufferInfo> infos(buffers.size());
    std::vector<VkBufferView> views(buffers.size());
    std::vector<VkWriteDescriptorSet> writes(buffers.size());
    for (std::uint32_t b = 0; b < buffers.size(); ++b) {
        writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        if (const VkDeviceSize bytes = texelBytes(b); bytes > 0) {
            views[b] = bytes == DeviceBuffer::kTexelBytes  ? buffers[b]->texelView()
                       : bytes == DeviceBuffer::kWordBytes ? buffers[b]->wordView()
                                                           : buffers[b]->floatView();
            if (views[b] == VK_NULL_HANDLE)
                throw Error("kernel " + mSpec.name + ": binding " + std::to_string(b) +
                            " reads buffer \"" + buffers[b]->name() + "\" (" +
                            std::to_string(buffers[b]->bytes()) + " bytes) as " +
                            std::to_string(bytes) +
                            "-byte texels, but it is smaller than one texel or larger than the "
                            "texel buffer limit");
            writes[b].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
            writes[b].pTexelBufferView = &views[b];
        } else {
            infos[b] = {buffers[b]->handle(), 0, VK_WHOLE_SIZE};
            writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[b].pBufferInfo = &infos[b];
        }
    }
    vkCmdBindPipeline(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline.get());
    mContext.cmdPushDescriptorSet()(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE,
                                    mPipelineLayout.get(), 0, std::uint32_t(writes.size()),
                                    writes.data());
    if (!pushConstants.empty())
        vkCmdPushConstants(commandBuffer, mPipelineLayout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           std::uint32_t(pushConstants.size()), pushConstants.data());
}

void ComputeKernel::record(VkCommandBuffer commandBuffer,
                           std::span<const DeviceBuffer* const> buffers,
                           std::span<const std::byte> pushConstants,
                           std::uint32_t groupCount) const {
    const std::uint32_t maxGroups = mContext.properties().limits.maxComputeWorkGroupCount[0];
    if (groupCount == 0 || groupCount > maxGroups)
        throw Error("kernel " + mSpec.name + ": group count " + std::to_string(groupCount) +
                    " is outside 1…" + std::to_string(maxGroups));
    bind(commandBuffer, buffers, pushConstants);
    vkCmdDispatch(commandBuffer, groupCount, 1, 1);
}

void ComputeKernel::recordIndirect(VkCommandBuffer commandBuffer,
                                   std::span<const DeviceBuffer* const> buffers,
                                   std::span<const std::byte> pushConstants,
                                   const DeviceBuffer& arguments, VkDeviceSize offset) const {
    if (offset % 4 != 0 || offset + sizeof(VkDispatchIndirectCommand) > arguments.bytes())
        throw Error("kernel " + mSpec.name + ": indirect arguments at byte " +
                    std::to_string(offset) + " do not fit buffer \"" + arguments.name() +
                    "\" (or are not 4-byte aligned)");
    bind(commandBuffer, buffers, pushConstants);
    vkCmdDispatchIndirect(commandBuffer, arguments.handle(), offset);
}

}  // namespace modeflow::vulkan
