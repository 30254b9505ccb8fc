#include "engine/display/Window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

#include "engine/core/Error.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::display {
namespace {

/// GLFW reports errors through a callback; the last one explains a failed call.
std::string lastGlfwError;

void recordGlfwError(int code, const char* description) {
    lastGlfwError = std::string(description) + " (GLFW error " + std::to_string(code) + ")";
}

Window& owner(GLFWwindow* window) {
    return *static_cast<Window*>(glfwGetWindowUserPointer(window));
}

/// Initializes GLFW, or says why there is no display.
void initializeGlfw() {
    glfwSetErrorCallback(recordGlfwError);
    if (glfwInit() != GLFW_TRUE)
        throw Error("cannot open a window: no display (" + lastGlfwError +
                    "). Set DISPLAY to an X server, or run headless under "
                    "xvfb-run -a -s \"-screen 0 1280x720x24\"");
}

}  // namespace

void Window::requireDisplay() {
    initializeGlfw();
    glfwTerminate();
}

Window::Window(int width, int height, const std::string& title) {
    initializeGlfw();
    if (glfwVulkanSupported() != GLFW_TRUE) {
        glfwTerminate();
        throw Error("cannot open a window: GLFW finds no Vulkan loader (" + lastGlfwError + ")");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    mWindow = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        glfwTerminate();
        throw Error("cannot create a " + std::to_string(width) + " × " + std::to_string(height) +
                    " window: " + lastGlfwError);
    }
    glfwSetWindowUserPointer(mWindow, this);
    glfwSetCursorPosCallback(mWindow, onCursor);
    glfwSetMouseButtonCallback(mWindow, onButton);
    glfwSetKeyCallback(mWindow, onKey);
    glfwSetScrollCallback(mWindow, onScroll);
}

Window::~Window() {
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() const {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("GLFW cannot present with Vulkan here: " + lastGlfwError);
    return {names, names + count};
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    vulkan::check(glfwCreateWindowSurface(instance, mWindow, nullptr, &surface),
                  "glfwCreateWindowSurface");
    return surface;
}

VkExtent2D Window::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(mWindow, &w, &h);
    return {std::uint32_t(std::max(w, 0)), std::uint32_t(std::max(h, 0))};
}

std::vector<InputEvent> Window::poll() {
    glfwPollEvents();
    return std::exchange(mEvents, {});
}

bool Window::closeRequested() const {
    return glfwWindowShouldClose(mWindow) == GLFW_TRUE;
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(mWindow, title.c_str());
}

void Window::resize(int width, int height) {
    glfwSetWindowSize(mWindow, width, height);
}

void Window::pointer(double& x, double& y) const {
    int w = 1, h = 1;
    glfwGetWindowSize(mWindow, &w, &h);
    glfwGetCursorPos(mWindow, &x, &y);
    x /= std::max(w, 1);
    y /= std::max(h, 1);
}

void Window::onCursor(GLFWwindow* window, double, double) {
    Window& self = owner(window);
    InputEvent e{InputKind::Move};
    self.pointer(e.x, e.y);
    self.mEvents.push_back(e);
}

void Window::onButton(GLFWwindow* window, int button, int action, int) {
    if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
    Window& self = owner(window);
    InputEvent e{action == GLFW_PRESS ? InputKind::ButtonDown : InputKind::ButtonUp};
    e.button = button == GLFW_MOUSE_BUTTON_LEFT ? MouseButton::Left : MouseButton::Right;
    self.pointer(e.x, e.y);
    self.mEvents.push_back(e);
}

void Window::onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_RELEASE) return;
    InputEvent e{InputKind::Key};
    e.key = key;
    owner(window).mEvents.push_back(e);
}

void Window::onScroll(GLFWwindow* window, double, double dy) {
    InputEvent e{InputKind::Scroll};
    e.y = dy;
    owner(window).mEvents.push_back(e);
}

}  // namespace modeflow::display
