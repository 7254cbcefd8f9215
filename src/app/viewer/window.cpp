#define GLFW_INCLUDE_VULKAN
#include "app/viewer/window.h"

#include <GLFW/glfw3.h>

#include <cstdio>

#include "core/error.h"
#include "gpu/check.h"

namespace penumbra::viewer {
namespace {

void onGlfwError(int code, const char* description) {
    std::fprintf(stderr, "penumbra: warning: GLFW error %d: %s\n", code, description ? description : "");
}

}  // namespace

Window::Window(int width, int height, const std::string& title) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throw Error("cannot open a window: no display (set DISPLAY, or run under xvfb-run for a virtual one)");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("GLFW found no Vulkan loader; install libvulkan1 and a Vulkan driver");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws; no OpenGL context
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw Error("GLFW could not create a window");
    }
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

VkExtent2D Window::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {static_cast<std::uint32_t>(w > 0 ? w : 0), static_cast<std::uint32_t>(h > 0 ? h : 0)};
}

std::vector<std::string> Window::requiredInstanceExtensions() {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw Error("GLFW cannot present with this Vulkan driver (no surface extensions)");
    return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    PN_VK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

}  // namespace penumbra::viewer
