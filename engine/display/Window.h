#pragma once
/// @file Window.h
/// One GLFW window without a graphics API of its own (Vulkan draws into it through a surface;
/// Swapchain.h), and the input it receives as InputEvents. GLFW is initialized for the window's
/// lifetime, so there is one Window at a time.

#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/display/InputEvent.h"

struct GLFWwindow;

namespace modeflow::display {

class Window {
public:
    /// Opens a width × height window (screen units) titled `title`.
    /// @throw modeflow::Error when there is no display (DISPLAY unset or unreachable: the
    ///        message says so and how to run headless), when GLFW finds no Vulkan loader, or
    ///        when the window cannot be created.
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    /// Throws the error the constructor would when there is no display, without opening a
    /// window (to refuse early, before long work).
    static void requireDisplay();

    /// The instance extensions a surface of this window needs.
    std::vector<std::string> requiredInstanceExtensions() const;
    /// A surface of this window on `instance`; the caller destroys it (VulkanContext does).
    /// @throw modeflow::Error when GLFW cannot create it.
    VkSurfaceKHR createSurface(VkInstance instance) const;

    /// The drawable size in pixels (0 × 0 while minimized).
    VkExtent2D framebufferSize() const;
    /// Processes the window system's events and returns the input since the last call.
    std::vector<InputEvent> poll();
    /// True once the user asked to close the window.
    bool closeRequested() const;
    void setTitle(const std::string& title);
    /// Asks the window system for a new size (screen units); framebufferSize() follows.
    void resize(int width, int height);

private:
    static void onCursor(GLFWwindow* window, double x, double y);
    static void onButton(GLFWwindow* window, int button, int action, int mods);
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    /// The pointer as fractions of the window.
    void pointer(double& x, double& y) const;

    GLFWwindow* mWindow = nullptr;
    std::vector<InputEvent> mEvents;
};

}  // namespace modeflow::display
