/// @file VulkanContextTest.cpp
/// The Vulkan foundation: device choice and its explanation, validation switch, buffers, fills.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/DeviceSelector.h"
#include "engine/vulkan/KernelVariants.h"
#include "engine/vulkan/StagingArea.h"
#include "engine/vulkan/VulkanError.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow {
namespace {

using testing::VulkanTest;
using vulkan::DeviceBuffer;
using vulkan::DeviceSelector;
using vulkan::VulkanContext;
using vulkan::VulkanContextOptions;

class VulkanContextTest : public VulkanTest {};

TEST_P(VulkanContextTest, FindsADeviceAndSaysWhyItWasChosen) {
    const std::string text = context().describe();
    std::cout << text;
    EXPECT_NE(text.find("Vulkan device: " + context().deviceName()), std::string::npos) << text;
    EXPECT_NE(text.find("chosen   #"), std::string::npos) << text;
    EXPECT_NE(text.find(GetParam() ? "validation on" : "validation "), std::string::npos) << text;
    EXPECT_NE(context().device(), VK_NULL_HANDLE);
    EXPECT_NE(context().queue(), VK_NULL_HANDLE);
}

TEST_P(VulkanContextTest, DeviceNameOptionPicksTheNamedDevice) {
    VulkanContextOptions options;
    options.validation = GetParam();
    options.deviceName = context().deviceName().substr(0, 4);
    const VulkanContext named(options);
    EXPECT_EQ(named.deviceName(), context().deviceName());
    EXPECT_EQ(named.validationMessageCount(), 0u);
}

TEST_P(VulkanContextTest, UnknownDeviceNameIsRefusedWithReasons) {
    VulkanContextOptions options;
    options.validation = GetParam();
    options.deviceName = "no-such-gpu-xyz";
    try {
        const VulkanContext named(options);
        FAIL() << "a context was made on " << named.deviceName();
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("no suitable Vulkan device"), std::string::npos) << message;
        EXPECT_NE(message.find("rejected #0"), std::string::npos) << message;
        EXPECT_NE(message.find("name does not contain \"no-such-gpu-xyz\""), std::string::npos)
            << message;
    }
}

TEST_P(VulkanContextTest, DeviceIndexOutOfRangeIsRefusedWithReasons) {
    VulkanContextOptions options;
    options.validation = GetParam();
    options.deviceIndex = 99;
    try {
        const VulkanContext indexed(options);
        FAIL() << "a context was made on " << indexed.deviceName();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("not the requested device index 99"),
                  std::string::npos)
            << e.what();
    }
}

TEST_P(VulkanContextTest, DeviceIndexZeroIsAccepted) {
    VulkanContextOptions options;
    options.validation = GetParam();
    options.deviceIndex = 0;
    const VulkanContext indexed(options);
    EXPECT_NE(indexed.describe().find("chosen   #0"), std::string::npos) << indexed.describe();
}

/// Whole and partial uploads and downloads give back what went in.
void expectRoundTrip(const vulkan::VulkanContext& context) {
    std::vector<float> values(1000);
    std::iota(values.begin(), values.end(), -3.5f);
    DeviceBuffer buffer = DeviceBuffer::fromValues<float>(context, values, "round trip");
    EXPECT_EQ(buffer.bytes(), values.size() * sizeof(float));
    EXPECT_EQ(buffer.isMapped(), !context.usesStaging());
    std::vector<float> back(values.size(), 0.0f);
    buffer.download<float>(back);
    EXPECT_EQ(back, values);

    // A partial upload at an offset changes only its range.
    const std::vector<float> patch{7.0f, 8.0f};
    buffer.upload<float>(patch, 10 * sizeof(float));
    buffer.download<float>(back);
    EXPECT_EQ(back[9], values[9]);
    EXPECT_EQ(back[10], 7.0f);
    EXPECT_EQ(back[11], 8.0f);
    EXPECT_EQ(back[12], values[12]);
    std::vector<float> two(2);
    buffer.download<float>(two, 11 * sizeof(float));
    EXPECT_EQ(two[0], 8.0f);
    EXPECT_THROW(buffer.upload<float>(patch, 999 * sizeof(float)), Error);
}

TEST_P(VulkanContextTest, BufferRoundTripsItsContents) {
    expectRoundTrip(context());
    expectNoValidationMessages();
}

TEST(VulkanStagingTest, DeviceLocalBuffersRoundTripThroughStaging) {
    // What discrete GPUs do, forced on whatever device runs the tests.
    vulkan::VulkanContextOptions options;
    options.forceStaging = true;
    options.validation = true;
    const vulkan::VulkanContext context(options);
    ASSERT_TRUE(context.usesStaging());
    EXPECT_NE(context.describe().find("staging"), std::string::npos);
    expectRoundTrip(context);
    EXPECT_EQ(context.validationMessageCount(), 0u);
}

TEST(VulkanStagingTest, TransfersLargerThanTheStagingBufferGoInPieces) {
    vulkan::VulkanContextOptions options;
    options.forceStaging = true;
    const vulkan::VulkanContext context(options);
    // One chunk and a bit, from an odd offset, so that the pieces' offsets must add up.
    const std::size_t count = (vulkan::StagingArea::kChunkBytes + 4096) / sizeof(std::uint32_t);
    std::vector<std::uint32_t> values(count);
    std::iota(values.begin(), values.end(), 12345u);
    DeviceBuffer buffer(context, (count + 3) * sizeof(std::uint32_t), "large");
    buffer.upload<std::uint32_t>(values, 3 * sizeof(std::uint32_t));
    std::vector<std::uint32_t> back(count + 3, 0u);
    buffer.download<std::uint32_t>(back);
    EXPECT_TRUE(std::equal(values.begin(), values.end(), back.begin() + 3));
    // The staging buffer kept from it serves small copies too.
    std::vector<std::uint32_t> few(5);
    buffer.download<std::uint32_t>(few, (count - 2) * sizeof(std::uint32_t));
    EXPECT_EQ(few[0], values[count - 5]);
    EXPECT_EQ(few[4], values[count - 1]);
}

TEST(VulkanStagingTest, TheStagingBufferGrowsNoLargerThanTheDeviceAllows) {
    // Growing by doubling from 600 bytes would pass a 1000-byte storage buffer limit.
    vulkan::VulkanContextOptions options;
    options.forceStaging = true;
    options.storageBufferLimit = 1000;
    const vulkan::VulkanContext context(options);
    for (const std::size_t bytes : {600u, 700u, 1000u}) {
        std::vector<std::uint8_t> values(bytes);
        std::iota(values.begin(), values.end(), std::uint8_t(bytes));
        DeviceBuffer buffer = DeviceBuffer::fromValues<std::uint8_t>(context, values, "limited");
        std::vector<std::uint8_t> back(bytes);
        buffer.download<std::uint8_t>(back);
        EXPECT_EQ(back, values) << bytes << " bytes";
    }
}

TEST_P(VulkanContextTest, BufferOverMaxStorageBufferRangeIsRefusedClearly) {
    const VkDeviceSize limit = context().properties().limits.maxStorageBufferRange;
    try {
        const DeviceBuffer buffer(context(), limit + 1, "too big");
        FAIL() << "a buffer of " << buffer.bytes() << " bytes was made";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("maxStorageBufferRange"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(limit)), std::string::npos) << message;
        EXPECT_NE(message.find("too big"), std::string::npos) << message;
    }
    EXPECT_THROW(DeviceBuffer(context(), 0, "empty"), Error);
}

TEST_P(VulkanContextTest, BuffersOfWholeTexelsCanBeReadAsTexels) {
    // Kernels read read-only streams as uniform texel buffers of 16-byte texels (RGBA32UI).
    const VkDeviceSize texelLimit =
        VkDeviceSize(context().properties().limits.maxTexelBufferElements) *
        DeviceBuffer::kTexelBytes;
    EXPECT_EQ(context().texelBufferLimit(), std::min(context().storageBufferLimit(), texelLimit));
    EXPECT_NE(DeviceBuffer(context(), 16, "one texel").texelView(), VK_NULL_HANDLE);
    // The view covers the whole texels; the ragged tail is read some other way.
    EXPECT_NE(DeviceBuffer(context(), 20, "one texel and a float").texelView(), VK_NULL_HANDLE);
    EXPECT_EQ(DeviceBuffer(context(), 12, "three floats").texelView(), VK_NULL_HANDLE);
    // And as 8-byte words (RG32UI), from one word up.
    EXPECT_NE(DeviceBuffer(context(), 12, "one word and a float").wordView(), VK_NULL_HANDLE);
    EXPECT_EQ(DeviceBuffer(context(), 4, "one float").wordView(), VK_NULL_HANDLE);
    // And as 32-bit values (R32UI).
    EXPECT_NE(DeviceBuffer(context(), 4, "one float").floatView(), VK_NULL_HANDLE);
    // A texel binding must be one of the kernel's bindings (checked before any SPIR-V is read).
    try {
        const vulkan::ComputeKernel kernel(context(), {"probe", {}, 2, 0, 64, {}, {2}});
        FAIL() << "a kernel with texel binding 2 of 2 bindings was made";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("texel binding 2"), std::string::npos) << message;
        EXPECT_NE(message.find("probe"), std::string::npos) << message;
    }
    try {
        const vulkan::ComputeKernel kernel(context(), {"probe", {}, 2, 0, 64, {}, {}, {3}});
        FAIL() << "a kernel with word binding 3 of 2 bindings was made";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("word binding 3"), std::string::npos) << e.what();
    }
    try {
        const vulkan::ComputeKernel kernel(context(), {"probe", {}, 2, 0, 64, {}, {}, {}, {2}});
        FAIL() << "a kernel with float binding 2 of 2 bindings was made";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("float binding 2"), std::string::npos) << e.what();
    }
    // Variants are made when first asked for, with the same checks.
    const vulkan::KernelVariants variants(context(), {"variant probe", {}, 2, 0, 64, {}, {2}});
    try {
        variants.with({1});
        FAIL() << "a variant with texel binding 2 of 2 bindings was made";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("variant probe"), std::string::npos) << e.what();
    }
    try {
        const vulkan::ComputeKernel kernel(context(), {"probe", {}, 2, 0, 64, {}, {1}, {}, {1}});
        FAIL() << "a kernel reading binding 1 through two views was made";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("binding 1 is listed as texels twice"),
                  std::string::npos)
            << e.what();
    }
    expectNoValidationMessages();
}

TEST_P(VulkanContextTest, ViewsShareTheirBuffersMemory) {
    std::vector<float> values(256);
    std::iota(values.begin(), values.end(), 0.0f);
    DeviceBuffer whole = DeviceBuffer::fromValues<float>(context(), values, "whole");
    DeviceBuffer second(whole, DeviceBuffer::kViewAlignment, 128 * sizeof(float), "second half");
    std::vector<float> read(2);
    second.download<float>(read);
    EXPECT_EQ(read[0], 64.0f);  // 256 bytes in
    EXPECT_EQ(read[1], 65.0f);
    const std::vector<float> patch{-1.0f};
    second.upload<float>(patch, 4 * sizeof(float));
    whole.download<float>(read, 68 * sizeof(float));
    EXPECT_EQ(read[0], -1.0f) << "a write through the view reaches the whole buffer";
    EXPECT_NE(second.texelView(), VK_NULL_HANDLE);
    EXPECT_THROW(DeviceBuffer(whole, 16, 16, "misaligned"), Error);
    EXPECT_THROW(DeviceBuffer(whole, DeviceBuffer::kViewAlignment, whole.bytes(), "past the end"),
                 Error);
    expectNoValidationMessages();
}

TEST_P(VulkanContextTest, FillSetsTheFirstWordsOfABufferOrView) {
    std::vector<float> values(256);
    std::iota(values.begin(), values.end(), 0.0f);
    DeviceBuffer whole = DeviceBuffer::fromValues<float>(context(), values, "whole");
    DeviceBuffer second(whole, DeviceBuffer::kViewAlignment, 128 * sizeof(float), "second half");
    vulkan::CommandSequence sequence(context());
    float word = 2.5f;
    std::uint32_t bits = 0;
    std::memcpy(&bits, &word, sizeof bits);
    sequence.fill(second, 8 * sizeof(float), bits);
    sequence.submitAndWait();
    std::vector<float> read(256);
    whole.download<float>(read);
    for (int i = 0; i < 256; ++i)
        EXPECT_EQ(read[i], i >= 64 && i < 72 ? 2.5f : float(i)) << "float " << i;
    EXPECT_THROW(sequence.fill(second, 6, 0u), Error);  // not whole words
    EXPECT_THROW(sequence.fill(second, 0, 0u), Error);
    EXPECT_THROW(sequence.fill(second, second.bytes() + 4, 0u), Error);
    expectNoValidationMessages();
}

TEST_P(VulkanContextTest, TimedDispatchesAreLabelledWithWhatTheyRan) {
    if (context().timestampValidBits() == 0) GTEST_SKIP() << "the queue writes no timestamps";
    const std::vector<float> values{1.0f, 2.0f};
    DeviceBuffer from = DeviceBuffer::fromValues<float>(context(), values, "from");
    DeviceBuffer to(context(), 2 * sizeof(float), "to");
    vulkan::CommandSequence sequence(context(), true, 4);
    sequence.keepNextRecording();
    sequence.fill(to, to.bytes(), 0u);
    sequence.copy(from, to, from.bytes());
    sequence.submitAndWait();
    const std::vector<std::string> labels{"fill to", "copy to"};
    EXPECT_EQ(sequence.dispatchLabels(), labels);
    EXPECT_EQ(sequence.dispatchTimesMs().size(), labels.size());
    sequence.resubmit();
    EXPECT_EQ(sequence.dispatchLabels(), labels) << "a kept recording keeps its labels";
    sequence.setTiming(false);
    sequence.copy(from, to, from.bytes());
    sequence.submitAndWait();
    EXPECT_TRUE(sequence.dispatchLabels().empty()) << "untimed";
    sequence.setTiming(true);
    sequence.copy(to, from, to.bytes());
    sequence.submitAndWait();
    EXPECT_EQ(sequence.dispatchLabels(), std::vector<std::string>{"copy from"});
    expectNoValidationMessages();
}

TEST_P(VulkanContextTest, KeptRecordingsResubmitWithWhatTheHostWroteSince) {
    std::vector<float> values{1.0f, 2.0f, 3.0f, 4.0f};
    DeviceBuffer from = DeviceBuffer::fromValues<float>(context(), values, "from");
    DeviceBuffer to(context(), 4 * sizeof(float), "to");
    vulkan::CommandSequence sequence(context());
    EXPECT_THROW(sequence.resubmit(), Error) << "nothing kept yet";
    sequence.keepNextRecording();
    sequence.copy(from, to, 3 * sizeof(float));
    EXPECT_THROW(sequence.keepNextRecording(), Error) << "while recording";
    EXPECT_THROW(sequence.resubmit(), Error) << "while recording";
    sequence.submitAndWait();
    ASSERT_TRUE(sequence.hasKeptRecording());
    std::vector<float> read(4);
    to.download<float>(read);
    EXPECT_EQ(std::vector<float>(read.begin(), read.begin() + 3),
              std::vector<float>(values.begin(), values.begin() + 3));
    // The step recorded once sees what the host writes between its submissions.
    for (float step = 1.0f; step <= 3.0f; ++step) {
        const std::vector<float> next{10.0f * step, 20.0f * step, 30.0f * step, -1.0f};
        from.upload<float>(next);
        sequence.resubmit();
        to.download<float>(read);
        EXPECT_EQ(read[0], 10.0f * step);
        EXPECT_EQ(read[2], 30.0f * step);
    }
    // Recording anything new drops it; a plain recording is not kept.
    sequence.fill(to, 4 * sizeof(float), 0u);
    EXPECT_FALSE(sequence.hasKeptRecording());
    sequence.submitAndWait();
    EXPECT_FALSE(sequence.hasKeptRecording());
    EXPECT_THROW(sequence.resubmit(), Error);
    to.download<float>(read);
    EXPECT_EQ(read[0], 0.0f);
    EXPECT_THROW(sequence.copy(from, to, 5 * sizeof(float)), Error);  // past `to`
    EXPECT_THROW(sequence.copy(from, to, 0), Error);
    expectNoValidationMessages();
}

INSTANTIATE_TEST_SUITE_P(Vulkan, VulkanContextTest, ::testing::Bool(), testing::validationName);

TEST(VulkanValidationTest, MisuseIsCountedSoZeroCountsMeanSomething) {
    // The zero-message assertions elsewhere are only worth something if the counter sees real
    // messages: a buffer with no usage bits breaks VUID-VkBufferCreateInfo-usage-requiredbitmask.
    auto context = testing::makeVulkanContext(true);
    ASSERT_NE(context, nullptr);
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 64;
    info.usage = 0;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    const VkResult result = vkCreateBuffer(context->device(), &info, nullptr, &buffer);
    if (result == VK_SUCCESS && buffer != VK_NULL_HANDLE)
        vkDestroyBuffer(context->device(), buffer, nullptr);
    EXPECT_GE(context->validationMessageCount(), 1u);
    const auto messages = context->validationMessages();
    ASSERT_FALSE(messages.empty());
    EXPECT_NE(messages.front().find("usage"), std::string::npos) << messages.front();
}

TEST(VulkanErrorTest, NamesTheFailingCallAndItsResult) {
    try {
        vulkan::check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "vkQueueSubmit failed: VK_ERROR_DEVICE_LOST");
    }
    EXPECT_NO_THROW(vulkan::check(VK_SUCCESS, "vkQueueSubmit"));
    EXPECT_EQ(vulkan::resultName(VkResult(12345)), "VkResult(12345)");
}

TEST(DeviceSelectorTest, PrefersDiscreteThenIntegratedThenCpu) {
    EXPECT_LT(DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
              DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU));
    EXPECT_LT(DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
              DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU));
    EXPECT_LT(DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU),
              DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_CPU));
    EXPECT_LT(DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_CPU),
              DeviceSelector::typeRank(VK_PHYSICAL_DEVICE_TYPE_OTHER));
}

}  // namespace
}  // namespace modeflow
