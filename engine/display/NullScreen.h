#pragma once
/// @file NullScreen.h
/// A Screen without a window or a display: its size is what the constructor and resize() set
/// (a script's resize events), minimized for as many frames as minimizeFor() says, it has no
/// input of its own (a script brings it), and each picture presented is read back and kept, so
/// tests can look at what a window would show.

#include "engine/display/Screen.h"
#include "engine/preview/Image.h"

namespace modeflow::display {

class NullScreen final : public Screen {
public:
    /// A width × height pixel screen on `context`, which must outlive it; `blueFirst`: the byte
    /// order of a B8G8R8A8 swapchain rather than R8G8B8A8; `readsBack`: present() copies each
    /// picture to lastPicture() (tests), or only counts it (`stir --offscreen`, where a copy per
    /// frame would be time a window does not spend).
    NullScreen(const vulkan::VulkanContext& context, int width, int height, bool blueFirst = false,
               bool readsBack = true);

    const vulkan::VulkanContext& context() const override { return mContext; }
    std::vector<InputEvent> poll() override { return {}; }
    bool closeRequested() const override { return false; }
    /// Sizes below 0 count as 0 (nothing shown, as a minimized window).
    void resize(int width, int height) override;
    /// 0 × 0 while minimized.
    VkExtent2D nextPictureSize() override;
    VkExtent2D extent() const override { return mExtent; }
    bool blueFirst() const override { return mBlueFirst; }
    /// Reads the picture back into lastPicture() (when made to) and counts it.
    void present(const vulkan::DeviceBuffer& pixels) override;

    /// The next `frames` calls of nextPictureSize() answer 0 × 0, as for a minimized window.
    void minimizeFor(int frames) { mMinimizedFrames = frames; }
    /// The last picture presented, in RGBA byte order (empty before the first).
    const preview::Image& lastPicture() const { return mLast; }
    int presentedCount() const { return mPresented; }

private:
    const vulkan::VulkanContext& mContext;
    VkExtent2D mExtent{};
    bool mBlueFirst;
    bool mReadsBack;
    preview::Image mLast;
    int mPresented = 0;
    int mMinimizedFrames = 0;
};

}  // namespace modeflow::display
