#pragma once
/// @file CommandSequence.h
/// Several kernel dispatches recorded into one command buffer, with a barrier between each pair
/// (every dispatch sees what the previous ones wrote), submitted once and waited on with a fence
/// (Kompute's Sequence). With timestamps on, each dispatch is bracketed by two GPU timestamps and
/// dispatchTimesMs() gives its duration after the submission. After submitAndWait() the sequence
/// is empty again and can be recorded anew; or, kept (keepNextRecording()), the recording can be
/// submitted again and again without recording it anew (resubmit()): a step recorded once, what
/// changes from step to step living in buffers the host writes between submissions.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/vulkan/DeviceHandle.h"

namespace modeflow::vulkan {

class ComputeKernel;
class DeviceBuffer;
class VulkanContext;

class CommandSequence {
public:
    /// `timestamps`: time each dispatch, up to `maxTimedDispatches` per submission. Ignored (and
    /// isTiming() false) when the queue cannot write timestamps.
    /// @throw modeflow::Error if a creation call fails.
    explicit CommandSequence(const VulkanContext& context, bool timestamps = false,
                             std::uint32_t maxTimedDispatches = 64);

    /// Records one dispatch of `kernel` (see ComputeKernel::record), after a barrier when it is
    /// not the first of the submission.
    /// @throw modeflow::Error when more than maxTimedDispatches are recorded with timing on.
    void dispatch(const ComputeKernel& kernel, std::span<const DeviceBuffer* const> buffers,
                  std::span<const std::byte> pushConstants, std::uint32_t groupCount);

    template <typename Params>
    void dispatch(const ComputeKernel& kernel, std::span<const DeviceBuffer* const> buffers,
                  const Params& params, std::uint32_t groupCount) {
        dispatch(kernel, buffers, std::as_bytes(std::span(&params, 1)), groupCount);
    }

    /// dispatch() with group counts read from `arguments` at `offset`
    /// (ComputeKernel::recordIndirect).
    void dispatchIndirect(const ComputeKernel& kernel, std::span<const DeviceBuffer* const> buffers,
                          std::span<const std::byte> pushConstants, const DeviceBuffer& arguments,
                          VkDeviceSize offset);

    template <typename Params>
    void dispatchIndirect(const ComputeKernel& kernel, std::span<const DeviceBuffer* const> buffers,
                          const Params& params, const DeviceBuffer& arguments,
                          VkDeviceSize offset) {
        dispatchIndirect(kernel, buffers, std::as_bytes(std::span(&params, 1)), arguments, offset);
    }

    /// Records setting the first `bytes` of `buffer` to copies of `word` (vkCmdFillBuffer: a
    /// memset on lavapipe, far cheaper than a kernel writing zeros), after the same barrier as a
    /// dispatch, timed and counted as one.
    /// @throw modeflow::Error if `bytes` is 0, not a multiple of 4 or beyond the buffer.
    void fill(const DeviceBuffer& buffer, VkDeviceSize bytes, std::uint32_t word);

    /// Records copying the first `bytes` of `from` to the start of `to` (vkCmdCopyBuffer), after
    /// the same barrier as a dispatch, timed and counted as one.
    /// @throw modeflow::Error if `bytes` is 0 or beyond either buffer.
    void copy(const DeviceBuffer& from, const DeviceBuffer& to, VkDeviceSize bytes);

    /// Ends recording, submits once, waits on the fence (then the host may read the buffers),
    /// reads the timestamps and makes the sequence ready for new recording.
    /// @throw modeflow::Error if nothing was recorded or a call fails (e.g. VK_ERROR_DEVICE_LOST).
    void submitAndWait();

    /// Keeps the next recording (from its first command to its submitAndWait()) for resubmit().
    /// Recording anything after it drops it.
    /// @throw modeflow::Error while a recording is under way.
    void keepNextRecording();
    /// Whether a kept recording is there to resubmit.
    bool hasKeptRecording() const { return mKept; }
    /// Submits the kept recording again and waits, as submitAndWait() does (with its dispatch
    /// times when it was recorded timed).
    /// @throw modeflow::Error without a kept recording, while recording, or if a call fails.
    void resubmit();
    /// Drops the kept recording, if any: the next commands start a new one.
    void dropKeptRecording();

    /// Times the following submissions, or not. A timestamp costs lavapipe about as much as a
    /// small dispatch (timing every one made a stir step far slower: tools/README.md), so a
    /// caller that shows times a few times a second times a sample of its submissions. Between
    /// submissions only; without timestamps (constructor) it stays off.
    /// @throw modeflow::Error while a submission is being recorded.
    void setTiming(bool on);
    bool isTiming() const { return mQueryPool.isValid() && mTimingOn; }
    /// Dispatches recorded since the last submission (0 right after submitAndWait()).
    std::size_t dispatchCount() const { return mDispatchCount; }
    /// Duration of each dispatch of the last submission, in milliseconds (empty without timing).
    const std::vector<double>& dispatchTimesMs() const { return mTimesMs; }
    /// What each timed dispatch of the last submission was, beside dispatchTimesMs(): its
    /// kernel's name (ComputeKernel::name), "fill NAME" or "copy NAME" (the buffer written).
    const std::vector<std::string>& dispatchLabels() const { return mLabels; }

private:
    void beginIfNeeded();
    /// The barrier after the previous dispatch, the timestamps around this one (and its label),
    /// the count.
    void recordTimed(const std::string& label, const std::function<void()>& recordDispatch);
    /// Submits the ended command buffer, waits, and reads the times of its first `dispatches`
    /// dispatches when `timed`.
    void submitRecorded(std::size_t dispatches, bool timed);

    const VulkanContext& mContext;
    std::uint32_t mMaxTimed;
    DeviceHandle<VkCommandPool> mPool;  // frees its command buffer with it
    VkCommandBuffer mCommandBuffer = VK_NULL_HANDLE;
    DeviceHandle<VkFence> mFence;
    DeviceHandle<VkQueryPool> mQueryPool;
    bool mRecording = false;
    bool mTimingOn = true;
    bool mKeepNext = false;  ///< the recording under way (or the next) is kept
    bool mKept = false;      ///< the command buffer holds a kept recording
    std::size_t mKeptDispatches = 0;
    bool mKeptTimed = false;
    std::size_t mDispatchCount = 0;
    std::vector<double> mTimesMs;
    std::vector<std::string> mRecordingLabels;  ///< of the timed recording under way (or kept)
    std::vector<std::string> mLabels;           ///< of the last submission's times
};

}  // namespace modeflow::vulkan
