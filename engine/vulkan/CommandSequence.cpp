#include "engine/vulkan/CommandSequence.h"

#include <cstdint>
#include <functional>
#include <string>

#include "engine/core/Error.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/SyncObjects.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {
namespace {

/// Makes the writes of every earlier dispatch or copy on the queue (in this submission or an
/// earlier one: a barrier's first scope covers all commands before it in submission order)
/// visible to what follows.
void memoryBarrier(VkCommandBuffer commandBuffer, VkPipelineStageFlags dstStage,
                   VkAccessFlags dstAccess) {
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(commandBuffer,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         dstStage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

CommandSequence::CommandSequence(const VulkanContext& context, bool timestamps,
                                 std::uint32_t maxTimedDispatches)
    : mContext(context), mMaxTimed(maxTimedDispatches) {
    const VkDevice device = context.device();
    CommandPool commands = makeCommandPool(context, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
    mPool = std::move(commands.pool);
    mCommandBuffer = commands.buffer;
    mFence = makeFence(device);

    if (timestamps && context.timestampValidBits() > 0 && maxTimedDispatches > 0) {
        VkQueryPoolCreateInfo queryInfo{};
        queryInfo.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
        queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
        queryInfo.queryCount = 2 * maxTimedDispatches;
        VkQueryPool queryPool = VK_NULL_HANDLE;
        check(vkCreateQueryPool(device, &queryInfo, nullptr, &queryPool), "vkCreateQueryPool");
        mQueryPool = DeviceHandle<VkQueryPool>(device, queryPool, vkDestroyQueryPool);
    }
}

void CommandSequence::setTiming(bool on) {
    if (mRecording)
        throw Error("CommandSequence: timing switched while a submission is being recorded");
    mTimingOn = on;
}

void CommandSequence::keepNextRecording() {
    if (mRecording) throw Error("CommandSequence: a recording under way cannot be kept");
    mKeepNext = true;
}

void CommandSequence::dropKeptRecording() {
    if (!mKept) return;
    check(vkResetCommandPool(mContext.device(), mPool.get(), 0), "vkResetCommandPool");
    mKept = false;
}

void CommandSequence::resubmit() {
    if (!mKept || mRecording)
        throw Error(mRecording ? "CommandSequence: resubmitted while recording"
                               : "CommandSequence: no kept recording to resubmit");
    submitRecorded(mKeptDispatches, mKeptTimed);
}

void CommandSequence::beginIfNeeded() {
    if (mRecording) return;
    dropKeptRecording();
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = mKeepNext ? 0 : VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(mCommandBuffer, &begin), "vkBeginCommandBuffer");
    if (isTiming()) vkCmdResetQueryPool(mCommandBuffer, mQueryPool.get(), 0, 2 * mMaxTimed);
    mRecording = true;
}

void CommandSequence::dispatch(const ComputeKernel& kernel,
                               std::span<const DeviceBuffer* const> buffers,
                               std::span<const std::byte> pushConstants, std::uint32_t groupCount) {
    recordTimed(kernel.name(),
                [&] { kernel.record(mCommandBuffer, buffers, pushConstants, groupCount); });
}

void CommandSequence::dispatchIndirect(const ComputeKernel& kernel,
                                       std::span<const DeviceBuffer* const> buffers,
                                       std::span<const std::byte> pushConstants,
                                       const DeviceBuffer& arguments, VkDeviceSize offset) {
    recordTimed(kernel.name(), [&] {
        kernel.recordIndirect(mCommandBuffer, buffers, pushConstants, arguments, offset);
    });
}

void CommandSequence::fill(const DeviceBuffer& buffer, VkDeviceSize bytes, std::uint32_t word) {
    if (bytes == 0 || bytes % 4 != 0 || bytes > buffer.bytes())
        throw Error("CommandSequence: cannot fill " + std::to_string(bytes) + " bytes of \"" +
                    buffer.name() + "\" (" + std::to_string(buffer.bytes()) +
                    " bytes; whole words only)");
    recordTimed("fill " + buffer.name(),
                [&] { vkCmdFillBuffer(mCommandBuffer, buffer.handle(), 0, bytes, word); });
}

void CommandSequence::copy(const DeviceBuffer& from, const DeviceBuffer& to, VkDeviceSize bytes) {
    if (bytes == 0 || bytes > from.bytes() || bytes > to.bytes())
        throw Error("CommandSequence: cannot copy " + std::to_string(bytes) + " bytes from \"" +
                    from.name() + "\" (" + std::to_string(from.bytes()) + " bytes) to \"" +
                    to.name() + "\" (" + std::to_string(to.bytes()) + " bytes)");
    const VkBufferCopy region{0, 0, bytes};
    recordTimed("copy " + to.name(),
                [&] { vkCmdCopyBuffer(mCommandBuffer, from.handle(), to.handle(), 1, &region); });
}

void CommandSequence::recordTimed(const std::string& label,
                                  const std::function<void()>& recordDispatch) {
    if (isTiming() && mDispatchCount >= mMaxTimed)
        throw Error("CommandSequence: more than " + std::to_string(mMaxTimed) +
                    " timed dispatches in one submission (raise maxTimedDispatches)");
    beginIfNeeded();
    if (mDispatchCount == 0) mRecordingLabels.clear();
    if (isTiming()) mRecordingLabels.push_back(label);
    // Every dispatch may read what an earlier one wrote, as data or as indirect dispatch
    // arguments, in this submission or the previous ones (waiting on their fence does not make
    // their writes visible to this one; lavapipe really does read stale data without it). One
    // global barrier is enough and costs little next to a dispatch.
    memoryBarrier(mCommandBuffer,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT |
                      VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                      VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                      VK_ACCESS_TRANSFER_WRITE_BIT);
    const auto query = std::uint32_t(2 * mDispatchCount);
    if (isTiming())
        vkCmdWriteTimestamp(mCommandBuffer, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, mQueryPool.get(),
                            query);
    recordDispatch();
    if (isTiming())
        vkCmdWriteTimestamp(mCommandBuffer, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, mQueryPool.get(),
                            query + 1);
    ++mDispatchCount;
}

void CommandSequence::submitAndWait() {
    if (!mRecording || mDispatchCount == 0)
        throw Error("CommandSequence: nothing recorded to submit");
    // Make the last writes visible to the host reads that follow the fence.
    memoryBarrier(mCommandBuffer, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    mRecording = false;
    check(vkEndCommandBuffer(mCommandBuffer), "vkEndCommandBuffer");

    submitRecorded(mDispatchCount, isTiming());
    if (mKeepNext) {
        mKept = true;
        mKeptDispatches = mDispatchCount;
        mKeptTimed = isTiming();
        mKeepNext = false;
    } else {
        check(vkResetCommandPool(mContext.device(), mPool.get(), 0), "vkResetCommandPool");
    }
    mDispatchCount = 0;
}

void CommandSequence::submitRecorded(std::size_t dispatches, bool timed) {
    vulkan::submitAndWait(mContext, mCommandBuffer, mFence.get());
    const VkDevice device = mContext.device();

    mTimesMs.clear();
    mLabels.clear();
    if (timed) {
        mLabels = mRecordingLabels;
        std::vector<std::uint64_t> ticks(2 * dispatches);
        check(vkGetQueryPoolResults(device, mQueryPool.get(), 0, std::uint32_t(ticks.size()),
                                    ticks.size() * sizeof(std::uint64_t), ticks.data(),
                                    sizeof(std::uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults");
        const unsigned bits = mContext.timestampValidBits();
        const std::uint64_t mask = bits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << bits) - 1;
        const double msPerTick = double(mContext.properties().limits.timestampPeriod) * 1e-6;
        for (std::size_t d = 0; d < dispatches; ++d)
            mTimesMs.push_back(double(((ticks[2 * d + 1] & mask) - (ticks[2 * d] & mask)) & mask) *
                               msPerTick);
    }
}

}  // namespace modeflow::vulkan
