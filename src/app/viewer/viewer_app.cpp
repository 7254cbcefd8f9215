#include "app/viewer/viewer_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>

#include "app/scene_opener.h"
#include "app/viewer/camera_controller.h"
#include "app/viewer/edit_panel.h"
#include "app/viewer/presenter.h"
#include "app/viewer/screenshot.h"
#include "app/viewer/ui_panel.h"
#include "app/viewer/window.h"
#include "bvh/depth_boxes.h"
#include "core/error.h"
#include "render/interactive_renderer.h"
#include "render/scene_objects.h"

namespace penumbra::viewer {
namespace {

// Input state kept between GLFW callbacks and the loop.
struct InputState {
    float scroll = 0;
    bool pauseToggled = false, resetCamera = false, screenshot = false;
    double lastX = 0, lastY = 0;
    bool dragging = false;
    // Left button: a press and release within a few pixels, away from the panel, is a click.
    bool leftDown = false;
    double leftDownX = 0, leftDownY = 0;
};

float cameraSpeedFor(const Scene& scene) {
    const Aabb bounds = scene.bounds();
    const float sceneSize = bounds.empty() ? 1.0f : length(bounds.extent());
    return std::max(0.1f, 0.1f * sceneSize);
}

void select(const Scene& scene, std::uint32_t object, EditState& edit) {
    edit.object = object;
    if (object == kNoObject) return;
    edit.objectName = objectName(scene, object);
    edit.materialIndex = objectMaterial(scene, object);
    edit.material = scene.materials[edit.materialIndex];
    edit.position = objectCentre(scene, object);
}

// Applies the panel's edits to the scene and the renderer. Failures go to the panel as one line.
void applyEdits(Scene& scene, InteractiveRenderer& renderer, ViewSettings& settings, EditState& edit,
                const EditRequests& requests, CameraController& controller, PanelState& panel);

bool imguiWantsMouse() { return ImGui::GetIO().WantCaptureMouse; }
bool imguiWantsKeyboard() { return ImGui::GetIO().WantCaptureKeyboard; }

InputState* inputOf(GLFWwindow* w) { return static_cast<InputState*>(glfwGetWindowUserPointer(w)); }

// The torch: attached as the scene's last punctual light so the renderer can move it; when the
// scene did not ask for one it starts switched off.
void prepareTorch(Scene& scene, ViewSettings& settings) {
    settings.torch = scene.torch.enabled && scene.torch.intensity > 0;
    if (!settings.torch) {
        scene.torch.enabled = true;
        if (!(scene.torch.intensity > 0)) scene.torch.intensity = Torch{}.intensity;
        attachTorch(scene);
    }
    settings.torchColor = scene.torch.color;
    settings.torchIntensity = scene.torch.intensity;
    settings.torchRange = scene.torch.range;
}

std::string defaultScreenshotPath() {
    char name[64];
    std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "penumbra-%Y%m%d-%H%M%S.png", std::localtime(&now));
    return name;
}

}  // namespace

DebugView parseDebugView(const std::string& name) {
    const std::pair<const char*, DebugView> views[] = {
        {"none", DebugView::None},     {"normals", DebugView::Normals}, {"albedo", DebugView::Albedo},
        {"depth", DebugView::Depth},   {"motion", DebugView::Motion},   {"samples", DebugView::Samples},
        {"nodes", DebugView::HeatNodes}, {"triangles", DebugView::HeatTriangles}, {"boxes", DebugView::BvhBoxes}};
    for (const auto& [n, v] : views)
        if (name == n) return v;
    throw UsageError("--debug must be one of none, normals, albedo, depth, motion, samples, nodes, triangles, boxes (got '" +
                     name + "')");
}

void runViewer(Scene scene, const ViewerOptions& options) {
    ViewSettings settings;
    settings.apertureRadius = scene.camera.apertureRadius;
    settings.focusDistance = scene.camera.focusDistance;
    settings.samplesPerFrame = options.samplesPerFrame;
    settings.denoise = options.denoise;
    settings.debug = options.debug;
    prepareTorch(scene, settings);

    Window window(options.width, options.height, "penumbra - " + scene.name);
    gpu::ContextOptions ctxOptions;
    ctxOptions.deviceSelector = options.device;
    ctxOptions.instanceExtensions = Window::requiredInstanceExtensions();
    ctxOptions.createSurface = [&](VkInstance instance) { return window.createSurface(instance); };
    gpu::ContextResult result = gpu::Context::create(ctxOptions);
    if (!result.context) throw Error(result.error);
    gpu::Context& ctx = *result.context;

    InteractiveRenderer renderer(ctx, scene, true);
    Presenter presenter(ctx, window, options.vsync);
    UiLayer ui(ctx, window.get(), presenter);

    CameraController controller(scene.camera, cameraSpeedFor(scene));

    InputState input;
    glfwSetWindowUserPointer(window.get(), &input);
    // ImGui's GLFW backend installed its callbacks (and chains to previously set ones); ours are
    // set after, so they chain to ImGui's.
    static GLFWscrollfun imguiScroll = nullptr;
    static GLFWkeyfun imguiKey = nullptr;
    imguiScroll = glfwSetScrollCallback(window.get(), [](GLFWwindow* w, double x, double y) {
        if (imguiScroll) imguiScroll(w, x, y);
        if (!imguiWantsMouse()) inputOf(w)->scroll += float(y);
    });
    imguiKey = glfwSetKeyCallback(window.get(), [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        if (imguiKey) imguiKey(w, key, scancode, action, mods);
        if (action != GLFW_PRESS || imguiWantsKeyboard()) return;
        InputState* in = inputOf(w);
        if (key == GLFW_KEY_P) in->pauseToggled = true;
        if (key == GLFW_KEY_R) in->resetCamera = true;
        if (key == GLFW_KEY_F12) in->screenshot = true;
        if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
    });

    EditState edit;
    PanelState panel;
    panel.sceneName = scene.name;
    panel.vsync = options.vsync;
    panel.playing = options.frames.has_value();  // automation plays from the start
    panel.triangles = scene.triangleCount();
    panel.bvhNodes = renderer.sceneArrays().nodes.size();
    panel.bvhDepth = bvh::treeDepth(renderer.sceneArrays().nodes);
    panel.hasTorch = renderer.hasTorch();

    bool frameInFlight = false;  // a rendered frame was submitted and not yet finished
    std::uint32_t framesRendered = 0;
    std::string pendingScreenshot;
    auto last = std::chrono::steady_clock::now();
    double fpsSmoothed = 0;

    while (!window.shouldClose()) {
        // Paused: sleep until something happens (no fan noise); playing: just poll.
        if (panel.playing) glfwPollEvents();
        else glfwWaitEventsTimeout(0.1);
        auto now = std::chrono::steady_clock::now();
        float dt = std::min(std::chrono::duration<float>(now - last).count(), 0.25f);
        last = now;

        if (input.pauseToggled) panel.playing = !panel.playing;
        if (input.resetCamera || panel.resetCamera) controller.reset();
        if (input.screenshot) panel.screenshotRequested = true;
        input.pauseToggled = input.resetCamera = input.screenshot = panel.resetCamera = false;
        if (input.scroll != 0) controller.scaleSpeed(std::pow(1.25f, input.scroll));
        input.scroll = 0;

        GLFWwindow* w = window.get();
        CameraInput move;
        if (!ui.wantsKeyboard()) {
            auto key = [&](int k) { return glfwGetKey(w, k) == GLFW_PRESS ? 1.0f : 0.0f; };
            move.forward = key(GLFW_KEY_W) - key(GLFW_KEY_S);
            move.right = key(GLFW_KEY_D) - key(GLFW_KEY_A);
            move.up = key(GLFW_KEY_SPACE) - key(GLFW_KEY_C);
            move.turn = key(GLFW_KEY_Q) - key(GLFW_KEY_E);
            move.fast = key(GLFW_KEY_LEFT_SHIFT) + key(GLFW_KEY_RIGHT_SHIFT) > 0;
        }
        double mx = 0, my = 0;
        glfwGetCursorPos(w, &mx, &my);
        const bool rightHeld = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (rightHeld && input.dragging) {
            move.lookX = float(mx - input.lastX);
            move.lookY = float(my - input.lastY);
        }
        input.dragging = rightHeld && (input.dragging || !ui.wantsMouse());
        const bool leftHeld = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (leftHeld && !input.leftDown && !ui.wantsMouse()) {
            input.leftDown = true;
            input.leftDownX = mx;
            input.leftDownY = my;
        } else if (!leftHeld && input.leftDown) {
            input.leftDown = false;
            if (std::abs(mx - input.leftDownX) + std::abs(my - input.leftDownY) < 4.0) {
                // Window coordinates: the render is the window scaled, so the same ray.
                int ww = 0, wh = 0;
                glfwGetWindowSize(w, &ww, &wh);
                if (ww > 0 && wh > 0) {
                    const Pick pick = pickPixel(renderer.sceneArrays(), controller.camera(), std::uint32_t(ww),
                                                std::uint32_t(wh), float(mx), float(my));
                    if (edit.focusOnClick) {
                        if (pick.depth > 0) settings.focusDistance = pick.depth;
                        edit.focusOnClick = false;
                    } else {
                        select(scene, pick.object, edit);
                    }
                }
            }
        }
        input.lastX = mx;
        input.lastY = my;
        controller.update(move, dt);

        ui.newFrame();
        panel.cameraSpeed = controller.speed();
        if (dt > 0) fpsSmoothed = fpsSmoothed == 0 ? 1.0 / dt : 0.9 * fpsSmoothed + 0.1 / dt;
        panel.fps = fpsSmoothed;
        EditRequests requests;
        ui.drawPanel(settings, panel, renderer.stats(), edit, requests);
        applyEdits(scene, renderer, settings, edit, requests, controller, panel);
        presenter.setVsync(panel.vsync);

        if (!presenter.beginFrame()) {
            ImGui::EndFrame();
            continue;
        }
        // The previous frame has finished: its timings and its display buffer are readable.
        if (frameInFlight) {
            renderer.finishFrame();
            frameInFlight = false;
            if (!pendingScreenshot.empty()) {
                try {
                    writeScreenshot(ctx, renderer, pendingScreenshot);
                    panel.message = "saved " + pendingScreenshot;
                    std::fprintf(stderr, "penumbra: screenshot %s\n", pendingScreenshot.c_str());
                } catch (const Error& e) {
                    panel.message = e.what();
                    std::fprintf(stderr, "penumbra: error: %s\n", e.what());
                }
                pendingScreenshot.clear();
                if (options.frames) window.requestClose();
            }
            if (options.frames && framesRendered >= *options.frames && options.screenshot.empty()) window.requestClose();
        }

        VkCommandBuffer cmd = presenter.commandBuffer();
        VkExtent2D fb = window.framebufferSize();
        if (panel.playing) {
            auto scaled = [&](std::uint32_t side) {
                return std::max(1u, std::uint32_t(float(side) * std::clamp(settings.resolutionScale, 0.1f, 1.0f)));
            };
            renderer.resize(scaled(fb.width), scaled(fb.height));
            panel.renderWidth = renderer.width();
            panel.renderHeight = renderer.height();
            renderer.record(cmd, controller.camera(), settings);
            presenter.blitDisplay(renderer.display(), renderer.width(), renderer.height());
            frameInFlight = true;
            ++framesRendered;
            if (panel.screenshotRequested) pendingScreenshot = defaultScreenshotPath();
            if (options.frames && framesRendered == *options.frames && !options.screenshot.empty())
                pendingScreenshot = options.screenshot;
        } else {
            presenter.clear(0.08f, 0.08f, 0.09f);
            if (panel.screenshotRequested) panel.message = "press Play first: nothing is rendered yet";
        }
        panel.screenshotRequested = false;
        presenter.beginUi();
        ui.render(cmd);
        presenter.endFrame();
    }
    presenter.waitIdle();
}

}  // namespace penumbra::viewer

namespace penumbra::viewer {
namespace {

void applyEdits(Scene& scene, InteractiveRenderer& renderer, ViewSettings& settings, EditState& edit,
                const EditRequests& requests, CameraController& controller, PanelState& panel) {
    if (requests.clearSelection) edit.object = kNoObject;
    try {
        if (requests.materialChanged && edit.materialIndex < scene.materials.size()) {
            Material& target = scene.materials[edit.materialIndex];
            const bool emissionChanged = target.emission.x != edit.material.emission.x ||
                                         target.emission.y != edit.material.emission.y ||
                                         target.emission.z != edit.material.emission.z;
            target = edit.material;
            // Emitters are weighed by power in the light tables, so new emission rebuilds them.
            if (emissionChanged) renderer.rebuildScene(scene, true);
            else renderer.setMaterial(edit.materialIndex, target);
        }
        if (requests.moveObject && isObject(scene, edit.object)) {
            translateObject(scene, edit.object, edit.position - objectCentre(scene, edit.object));
            renderer.rebuildScene(scene, true);
            panel.bvhNodes = renderer.sceneArrays().nodes.size();
            panel.bvhDepth = bvh::treeDepth(renderer.sceneArrays().nodes);
        }
        if (requests.openScene) {
            app::OpenedScene opened = app::openSceneFile(edit.openPath);
            if (!opened.scene) {
                edit.openMessage = opened.error;
                std::fprintf(stderr, "penumbra: error: %s\n", opened.error.c_str());
                return;
            }
            Scene next = std::move(*opened.scene);
            ViewSettings nextSettings = settings;
            prepareTorch(next, nextSettings);
            renderer.rebuildScene(next, true);
            scene = std::move(next);
            settings = nextSettings;
            settings.apertureRadius = scene.camera.apertureRadius;
            settings.focusDistance = scene.camera.focusDistance;
            controller = CameraController(scene.camera, cameraSpeedFor(scene));
            edit.object = kNoObject;
            edit.openMessage.clear();
            panel.sceneName = scene.name;
            panel.triangles = scene.triangleCount();
            panel.bvhNodes = renderer.sceneArrays().nodes.size();
            panel.bvhDepth = bvh::treeDepth(renderer.sceneArrays().nodes);
            panel.hasTorch = renderer.hasTorch();
        }
    } catch (const Error& e) {
        // The renderer keeps its previous scene when a rebuild fails before the upload.
        edit.openMessage = e.what();
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
    }
}

}  // namespace
}  // namespace penumbra::viewer
