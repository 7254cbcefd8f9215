// The GLFW window: library lifetime, the window, and the instance extensions and surface Vulkan
// needs to present to it.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

struct GLFWwindow;

namespace penumbra::viewer {

class Window {
public:
    // Throws Error with a clear message when there is no display or GLFW has no Vulkan loader.
    Window(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* get() const { return window_; }
    bool shouldClose() const;
    void requestClose();
    VkExtent2D framebufferSize() const;  // 0 x 0 while minimised

    static std::vector<std::string> requiredInstanceExtensions();
    VkSurfaceKHR createSurface(VkInstance instance) const;

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace penumbra::viewer
