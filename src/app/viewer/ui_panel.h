// Dear ImGui (Debian's libimgui-dev, with its GLFW and Vulkan backends) and the settings panel.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "app/viewer/edit_panel.h"
#include "render/interactive_renderer.h"
#include "render/view_settings.h"

struct GLFWwindow;

namespace penumbra::viewer {

class Presenter;

// What the panel shows and what its buttons ask for.
struct PanelState {
    bool visible = true;  // Tab hides and shows the panel
    bool playing = false;
    bool vsync = true;
    bool screenshotRequested = false;
    bool resetCamera = false;
    std::string sceneName;
    std::uint32_t renderWidth = 0, renderHeight = 0;
    double fps = 0;
    float cameraSpeed = 0;
    std::size_t triangles = 0, bvhNodes = 0;
    std::size_t bvhDepth = 0;  // bvh::treeDepth, as `penumbra info` prints it: the box slider's top
    bool hasTorch = false;
    bool hasPhantom = false, phantom = true;  // the dungeon's phantom: the scene has one; shown (H)
    bool frameStatistics = false;  // the trace kernels count tests, hits and blocked shadow rays
    bool walking = false, canWalk = false, pointerCaptured = false;
    std::string message;  // last screenshot path or error
};

class UiLayer {
public:
    UiLayer(const gpu::Context& ctx, GLFWwindow* window, const Presenter& presenter);
    ~UiLayer();
    UiLayer(const UiLayer&) = delete;
    UiLayer& operator=(const UiLayer&) = delete;

    void newFrame();
    // Draws the panel, editing settings and state in place; edits to the scene become requests.
    void drawPanel(ViewSettings& settings, PanelState& state, const ViewerStats& stats, EditState& edit,
                   EditRequests& requests);
    void render(VkCommandBuffer cmd);  // inside the presenter's UI render pass
    bool wantsMouse() const;

private:
    void shutdown();  // ImGui's backends and context

    VkDevice device_;
    gpu::DescriptorPool pool_;
};

}  // namespace penumbra::viewer
