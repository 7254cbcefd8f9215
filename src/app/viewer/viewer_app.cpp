#include "app/viewer/viewer_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <limits>
#include <optional>
#include <utility>

#include "app/scene_opener.h"
#include "interact/controls.h"
#include "app/viewer/edit_panel.h"
#include "interact/navigation.h"
#include "interact/group_drag.h"
#include "interact/object_drag.h"
#include "interact/play_step.h"
#include "app/viewer/presenter.h"
#include "app/viewer/screenshot.h"
#include "app/viewer/ui_panel.h"
#include "app/viewer/window.h"
#include "bvh/depth_boxes.h"
#include "core/error.h"
#include "render/interactive_renderer.h"
#include "render/picking.h"
#include "scene/add_model.h"
#include "scene/animation.h"
#include "scene/sphere_groups.h"

namespace penumbra::viewer {
namespace {

// The pointer between frames: right-button drag, the captured pointer, and left clicks.
struct PointerState {
    double lastX = 0, lastY = 0;
    bool dragging = false;
    bool captured = false;  // hidden and locked to the window; its motion looks around
    // Left button: a press and release within a few pixels, away from the panel, is a click.
    bool leftDown = false;
    double leftDownX = 0, leftDownY = 0;
    // A left press on the selected instance grabs it: it follows the cursor until the release.
    std::optional<ObjectDrag> drag;
    std::optional<GroupDrag> groupDrag;  // the same for a selected sphere group
};

struct Click {
    double x = 0, y = 0;  // window coordinates
};

// What the left button did this frame: pressed (away from the panel) and clicked.
struct LeftButton {
    std::optional<Click> press, click;
};

void select(const Scene& scene, std::uint32_t object, EditState& edit) {
    edit.object = object;
    edit.group = kNoObject;
    if (object == kNoObject) return;
    edit.objectName = objectName(scene, object);
    edit.materialIndex = objectMaterial(scene, object);
    edit.material = scene.materials[edit.materialIndex];
    const bool sphere = object >= scene.meshes.size();
    const std::optional<std::uint32_t> group = sphere ? sphereGroupOf(scene, object - scene.meshes.size()) : std::nullopt;
    edit.group = group ? *group : kNoObject;
    if (group) edit.objectName = sphereGroupName(scene, *group) + ", " + edit.objectName;
    edit.turnDegrees = Vec3{0};
    edit.position = selectionCentre(scene, edit);
}

// Applies the panel's edits to the scene and the renderer. Failures go to the panel as one line.
void applyEdits(Scene& scene, InteractiveRenderer& renderer, ViewSettings& settings, EditState& edit,
                const EditRequests& requests, Navigation& nav, PanelState& panel);

bool imguiWantsMouse() { return ImGui::GetIO().WantCaptureMouse; }
bool imguiWantsKeyboard() { return ImGui::GetIO().WantCaptureKeyboard; }

InputState* inputOf(GLFWwindow* w) { return static_cast<InputState*>(glfwGetWindowUserPointer(w)); }

std::string defaultScreenshotPath() {
    char name[64];
    std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "penumbra-%Y%m%d-%H%M%S.png", std::localtime(&now));
    return name;
}

// Keys and the wheel go to the controls (controls.h); ImGui's GLFW backend installed its
// callbacks first, and ours chain to them. A press that ImGui takes (typing in a field) is not
// a control; releases always pass, so no key stays held.
void installCallbacks(GLFWwindow* window, InputState& input) {
    glfwSetWindowUserPointer(window, &input);
    static GLFWscrollfun imguiScroll = nullptr;
    static GLFWkeyfun imguiKey = nullptr;
    imguiScroll = glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
        if (imguiScroll) imguiScroll(w, x, y);
        if (!imguiWantsMouse()) inputOf(w)->scroll += float(y);
    });
    imguiKey = glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        if (imguiKey) imguiKey(w, key, scancode, action, mods);
        if (action == GLFW_PRESS && !imguiWantsKeyboard()) applyKey(*inputOf(w), key, true);
        if (action == GLFW_RELEASE) applyKey(*inputOf(w), key, false);
    });
}

void setCaptured(GLFWwindow* w, PointerState& pointer, bool on) {
    if (pointer.captured == on) return;
    pointer.captured = on;
    glfwSetInputMode(w, GLFW_CURSOR, on ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
    if (glfwRawMouseMotionSupported()) glfwSetInputMode(w, GLFW_RAW_MOUSE_MOTION, on ? GLFW_TRUE : GLFW_FALSE);
    // While captured the hidden pointer must not drive the panel.
    ImGuiIO& io = ImGui::GetIO();
    if (on) io.ConfigFlags |= ImGuiConfigFlags_NoMouse;
    else io.ConfigFlags &= ~ImGuiConfigFlags_NoMouse;
    glfwGetCursorPos(w, &pointer.lastX, &pointer.lastY);  // no jump on the next frame
    pointer.dragging = pointer.leftDown = false;
    pointer.drag.reset();
    pointer.groupDrag.reset();
}

// Pointer motion that looks (captured, or dragging with the right button), left presses and clicks.
LeftButton trackPointer(GLFWwindow* w, PointerState& p, InputState& input, bool uiWantsMouse) {
    double mx = 0, my = 0;
    glfwGetCursorPos(w, &mx, &my);
    LeftButton left;
    if (p.captured) {
        applyLook(input, float(mx - p.lastX), float(my - p.lastY));
        if (!glfwGetWindowAttrib(w, GLFW_FOCUSED)) setCaptured(w, p, false);  // focus lost: let go
    } else {
        const bool rightHeld = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (rightHeld && p.dragging) applyLook(input, float(mx - p.lastX), float(my - p.lastY));
        p.dragging = rightHeld && (p.dragging || !uiWantsMouse);
        const bool leftHeld = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (leftHeld && !p.leftDown && !uiWantsMouse) {
            p.leftDown = true;
            p.leftDownX = mx;
            p.leftDownY = my;
            left.press = Click{mx, my};
        } else if (!leftHeld && p.leftDown) {
            p.leftDown = false;
            const bool dragged = p.drag.has_value() || p.groupDrag.has_value();
            p.drag.reset();
            p.groupDrag.reset();
            // A press and release in place is a click, unless it grabbed the selection (walking,
            // a click captures the mouse, which would end the user's handling of the object).
            if (std::abs(mx - p.leftDownX) + std::abs(my - p.leftDownY) < 4.0 && !dragged) left.click = Click{mx, my};
        }
    }
    p.lastX = mx;
    p.lastY = my;
    return left;
}

// A left press on the selected instance grabs it (the CPU pick under the cursor, as a click's):
// to move it, or with Shift held to turn it.
void grabSelection(GLFWwindow* w, const Click& press, PointerState& pointer, const Scene& scene,
                   const InteractiveRenderer& renderer, const Camera& camera, std::uint32_t selectedInstance,
                   std::uint32_t selectedGroup) {
    int ww = 0, wh = 0;
    glfwGetWindowSize(w, &ww, &wh);
    if (ww <= 0 || wh <= 0) return;
    const bool shift =
        glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    pointer.drag = grabInstance(scene, renderer.sceneArrays(), camera, std::uint32_t(ww), std::uint32_t(wh),
                                float(press.x), float(press.y), selectedInstance, shift);
    if (!pointer.drag && selectedGroup != kNoObject)
        pointer.groupDrag = grabSphereGroup(scene, renderer.sceneArrays(), camera, std::uint32_t(ww), std::uint32_t(wh),
                                            float(press.x), float(press.y), selectedGroup, shift);
}

// Moves (or turns) a grabbed sphere group as the cursor moved; true when it moved. Its spheres are
// world data: the caller rebuilds the scene.
bool dragGroup(GLFWwindow* w, PointerState& pointer, Scene& scene, const Camera& camera) {
    if (!pointer.groupDrag) return false;
    int ww = 0, wh = 0;
    glfwGetWindowSize(w, &ww, &wh);
    if (ww <= 0 || wh <= 0) return false;
    return followCursor(*pointer.groupDrag, scene, camera, std::uint32_t(ww), std::uint32_t(wh), float(pointer.lastX),
                        float(pointer.lastY));
}

// Moves (or turns) a grabbed instance as the cursor moved; true when it moved.
bool dragSelection(GLFWwindow* w, PointerState& pointer, Scene& scene, const Camera& camera) {
    if (!pointer.drag) return false;
    int ww = 0, wh = 0;
    glfwGetWindowSize(w, &ww, &wh);
    if (ww <= 0 || wh <= 0) return false;
    return followCursor(*pointer.drag, scene, camera, std::uint32_t(ww), std::uint32_t(wh), float(pointer.lastX),
                        float(pointer.lastY));
}

// A click sets the focus (when asked), captures the pointer while walking, or selects.
void handleClick(GLFWwindow* w, const Click& click, PointerState& pointer, const Scene& scene,
                 const InteractiveRenderer& renderer, const Navigation& nav, const Camera& camera,
                 ViewSettings& settings, EditState& edit, std::uint32_t& selectedInstance, PanelState& panel) {
    if (nav.walking() && !edit.focusOnClick) {
        setCaptured(w, pointer, true);
        return;
    }
    // Window coordinates: the render is the window scaled, so the same ray.
    int ww = 0, wh = 0;
    glfwGetWindowSize(w, &ww, &wh);
    if (ww <= 0 || wh <= 0) return;
    const Pick pick = pickPixel(renderer.sceneArrays(), camera, std::uint32_t(ww), std::uint32_t(wh),
                                float(click.x), float(click.y));
    if (edit.focusOnClick) {
        if (pick.depth > 0) settings.focusDistance = pick.depth;
        edit.focusOnClick = false;
    } else {
        select(scene, pick.object, edit);
        selectedInstance = pick.instance;
        if (pick.instance < scene.instances.size())
            panel.message = instanceName(scene, pick.instance) + kInstanceControls;
    }
}

// The keys pressed (and the wheel turned) since the last frame, and the panel's buttons.
void handlePresses(InputState& input, GLFWwindow* w, PointerState& pointer, Navigation& nav, const Scene& scene,
                   PanelState& panel) {
    if (input.pauseToggled) panel.playing = !panel.playing;
    input.resetCamera = input.resetCamera || panel.resetCamera;
    panel.resetCamera = false;
    if (input.screenshot) panel.screenshotRequested = true;
    if (std::string message = nav.handlePresses(input, scene); !message.empty()) panel.message = message;
    if (input.panelToggled) panel.visible = !panel.visible;
    if (input.escape) {  // releases the captured mouse first; quits only when it is free
        if (pointer.captured) setCaptured(w, pointer, false);
        else glfwSetWindowShouldClose(w, GLFW_TRUE);
    }
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.lookAt == b.lookAt && a.up == b.up && a.fovYDegrees == b.fovYDegrees;
}

// What the last rendered frame showed, so a paused viewer renders again only when it changed.
struct ShownFrame {
    bool valid = false;
    Camera camera;
    ViewSettings settings;
    std::uint32_t width = 0, height = 0;

    bool matches(const Camera& c, const ViewSettings& s, std::uint32_t w, std::uint32_t h) const {
        return valid && sameCamera(camera, c) && settings == s && width == w && height == h;
    }
};

// What the frame loop carries from one frame to the next, besides the scene and its settings.
struct LoopState {
    Navigation nav;
    std::uint32_t selectedInstance = kNoObject;  // N cycles through the instances; a click picks one
    InputState input;
    PointerState pointer;
    std::optional<ScriptPlayer> script;
    EditState edit;
    PanelState panel;
    bool frameInFlight = false;  // a rendered frame was submitted and not yet finished
    ShownFrame shown;            // what the display buffer holds
    std::uint32_t framesRendered = 0;
    std::string pendingScreenshot;
    double fpsSmoothed = 0;
    double animationClock = 0;  // seconds played: the moment animated textures show
    bool levelEndedByScript = false;  // --script ended a Doom level: the viewer exits 0
    std::uint32_t stepsPerFrame = 1;  // --steps-per-frame: steps of play a drawn frame
    bool addModelKey = false;   // M was pressed: add the model named in the panel

    LoopState(const Scene& scene, const ViewerOptions& options, const InteractiveRenderer& renderer)
        : nav(scene, options.fly) {
        if (options.script) script.emplace(*options.script);
        stepsPerFrame = options.stepsPerFrame;
        panel.sceneName = scene.name;
        panel.vsync = options.vsync;
        panel.playing = options.frames.has_value() || script.has_value();  // automation plays from the start
        panel.triangles = scene.triangleCount();
        panel.bvhNodes = renderer.sceneArrays().nodes.size();
        panel.bvhDepth = bvh::treeDepth(renderer.sceneArrays().nodes);
        panel.hasTorch = renderer.hasTorch();
        panel.hasPhantom = nav.hasPhantom();
        panel.phantom = options.phantom;
        loadLights(scene, edit);
    }
    Camera camera() const { return nav.camera(); }
};

// One step of play (the camera, then the world): true when instances moved.
bool playOneStep(LoopState& loop, Scene& scene, InteractiveRenderer& renderer, GLFWwindow* w, float step) {
    const WorldChange change = playStep(scene, loop.nav, loop.input, loop.animationClock, step);
    for (std::uint32_t m : change.lightsChanged) renderer.setUnsampledEmission(m, scene.materials[m].emission);
    for (std::uint32_t m : change.materialsChanged) renderer.setMaterial(m, scene.materials[m]);
    if (change.levelCompleted) {
        std::printf("%s\n", change.levelCompleted->c_str());
        std::fflush(stdout);
        loop.panel.message = *change.levelCompleted;
        glfwSetWindowTitle(w, ("penumbra - " + scene.name + " - " + *change.levelCompleted).c_str());
        loop.levelEndedByScript = loop.script.has_value();  // a script that ends the level is done
    }
    if (change.geometryChanged) renderer.rebuildScene(scene, true);
    return change.instancesMoved;
}

// This frame's input (keys, pointer, script) moves the camera, the selected instance and the
// animation clock.
void applyInput(LoopState& loop, Scene& scene, InteractiveRenderer& renderer, const UiLayer& ui, GLFWwindow* w,
                ViewSettings& settings, float step, bool automationDone) {
    const bool advancing = loop.panel.playing && !automationDone;
    if (loop.script && advancing) loop.script->playFrame(loop.input, step);
    handlePresses(loop.input, w, loop.pointer, loop.nav, scene, loop.panel);
    if (loop.input.previewToggled) settings.preview = !settings.preview;
    if (loop.input.addModel) loop.addModelKey = true;
    if (loop.input.nextInstance && !scene.instances.empty()) {
        loop.selectedInstance = loop.selectedInstance + 1 < scene.instances.size() ? loop.selectedInstance + 1 : 0;
        loop.panel.message = instanceName(scene, loop.selectedInstance) + kInstanceControls;
    }
    const LeftButton left = trackPointer(w, loop.pointer, loop.input, ui.wantsMouse());
    if (left.press)
        grabSelection(w, *left.press, loop.pointer, scene, renderer, loop.camera(), loop.selectedInstance,
                      loop.edit.group);
    if (left.click)
        handleClick(w, *left.click, loop.pointer, scene, renderer, loop.nav, loop.camera(), settings, loop.edit,
                    loop.selectedInstance, loop.panel);
    // The selected instance moves with its keys, paused or playing; only the top level changes.
    bool instancesMoved = !automationDone && moveSelectedInstance(scene, loop.selectedInstance,
                                                                  objectInputFrom(loop.input), loop.camera(),
                                                                  loop.nav.speed(), step);
    // Paused, the camera stays where the shown frame was taken, and animated textures hold
    // their frame; playing, they run at the game's rate in simulated time (--fixed-dt too).
    if (advancing) {
        for (std::uint32_t k = 0; k < loop.stepsPerFrame && !loop.levelEndedByScript; ++k) {
            if (k > 0) {  // the next step's events and presses, as a frame of its own would see them
                endInputFrame(loop.input);
                if (loop.script) loop.script->playFrame(loop.input, step);
                handlePresses(loop.input, w, loop.pointer, loop.nav, scene, loop.panel);
            }
            if (playOneStep(loop, scene, renderer, w, step)) instancesMoved = true;
        }
        settings.time = float(loop.animationClock);
    }
    // The phantom's switch (H or the panel), paused or playing: parked or back on its patrol.
    if (loop.input.phantomToggled && loop.panel.hasPhantom) loop.panel.phantom = !loop.panel.phantom;
    if (loop.nav.showPhantom(scene, loop.panel.phantom, loop.animationClock)) instancesMoved = true;
    // A grabbed instance follows the cursor, after the camera and the animations have moved.
    if (!automationDone && dragSelection(w, loop.pointer, scene, loop.camera())) instancesMoved = true;
    if (!automationDone && dragGroup(w, loop.pointer, scene, loop.camera())) {
        renderer.rebuildScene(scene, true);
        loop.edit.position = selectionCentre(scene, loop.edit);
        loop.shown.valid = false;
    }
    if (instancesMoved) {
        renderer.setInstanceTransforms(scene);
        loop.shown.valid = false;
    }
    endInputFrame(loop.input);
}

void addModel(LoopState& loop, Scene& scene, InteractiveRenderer& renderer);

// The panel, and the edits it asks for.
void drawUi(LoopState& loop, Scene& scene, InteractiveRenderer& renderer, UiLayer& ui, ViewSettings& settings,
            float dt) {
    ui.newFrame();
    PanelState& panel = loop.panel;
    panel.cameraSpeed = loop.nav.speed();
    panel.walking = loop.nav.walking();
    panel.canWalk = loop.nav.canWalk();
    panel.pointerCaptured = loop.pointer.captured;
    if (dt > 0) loop.fpsSmoothed = loop.fpsSmoothed == 0 ? 1.0 / dt : 0.9 * loop.fpsSmoothed + 0.1 / dt;
    panel.fps = loop.fpsSmoothed;
    EditRequests requests;
    if (panel.visible) ui.drawPanel(settings, panel, renderer.stats(), loop.edit, requests);
    requests.addModel = requests.addModel || std::exchange(loop.addModelKey, false);
    applyEdits(scene, renderer, settings, loop.edit, requests, loop.nav, panel);
    if (requests.addModel) addModel(loop, scene, renderer);
    renderer.setFrameStatistics(panel.frameStatistics);
    if (requests.openScene) {  // nothing selected in the new scene
        loop.selectedInstance = kNoObject;
        loop.pointer.drag.reset();
        loop.pointer.groupDrag.reset();
    }
    if (requests.materialChanged || requests.moveObject || requests.turnGroup || requests.lightChanged ||
        requests.openScene)
        loop.shown.valid = false;
}

// Adds the model named in the panel in front of the camera as a new instance, and selects it so
// that it can be dragged and turned at once. A failure leaves the scene as it was.
void addModel(LoopState& loop, Scene& scene, InteractiveRenderer& renderer) {
    EditState& edit = loop.edit;
    if (edit.addPath.empty()) {
        edit.addMessage = "type a model's path (or a built-in scene's name) first";
        return;
    }
    app::OpenedScene opened = app::openSceneFile(edit.addPath);
    if (!opened.scene) {
        edit.addMessage = opened.error;
        std::fprintf(stderr, "penumbra: error: %s\n", opened.error.c_str());
        return;
    }
    try {
        Scene next = scene;
        // Half the depth of what the middle of the view shows: a model too large for that room
        // is scaled down to fit in front of it.
        const Camera camera = loop.camera();
        const Pick ahead = pickPixel(renderer.sceneArrays(), camera, 64, 64, 32.0f, 32.0f);
        const float room = ahead.depth > 0 ? 0.5f * ahead.depth : std::numeric_limits<float>::infinity();
        const AddedModel added = addModelInFront(next, std::move(*opened.scene), camera, room);
        renderer.rebuildScene(next, true);
        scene = std::move(next);
        loop.selectedInstance = added.instance;
        loop.panel.message = instanceName(scene, added.instance) + kInstanceControls;
        edit.addMessage = "added " + instanceName(scene, added.instance);
        loop.panel.bvhNodes = renderer.sceneArrays().nodes.size();
        loop.panel.bvhDepth = bvh::treeDepth(renderer.sceneArrays().nodes);
        loop.shown.valid = false;
    } catch (const Error& e) {
        edit.addMessage = e.what();
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
    }
}

// Once the previous frame has finished, its timings and its display buffer are readable: a
// screenshot asked for with it is written now.
void finishShownFrame(LoopState& loop, const gpu::Context& ctx, InteractiveRenderer& renderer) {
    if (!loop.frameInFlight) return;
    renderer.finishFrame();
    loop.frameInFlight = false;
    if (loop.pendingScreenshot.empty()) return;
    try {
        writeScreenshot(ctx, renderer, loop.pendingScreenshot);
        loop.panel.message = "saved " + loop.pendingScreenshot;
        std::fprintf(stderr, "penumbra: screenshot %s\n", loop.pendingScreenshot.c_str());
    } catch (const Error& e) {
        loop.panel.message = e.what();
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
    }
    loop.pendingScreenshot.clear();
}

// Playing renders every frame; paused renders one preview frame, again only when the camera, a
// setting or the size changed (or for a screenshot), and shows it meanwhile.
void renderOrShow(LoopState& loop, VkCommandBuffer cmd, InteractiveRenderer& renderer, Presenter& presenter,
                  VkExtent2D framebuffer, const ViewSettings& settings, const ViewerOptions& options,
                  bool automationDone) {
    auto scaled = [&](std::uint32_t side) {
        return scaledSide(side, settings.resolutionScale);
    };
    const std::uint32_t rw = scaled(framebuffer.width), rh = scaled(framebuffer.height);
    const Camera camera = loop.camera();
    PanelState& panel = loop.panel;
    if (!automationDone && (panel.playing || panel.screenshotRequested || !loop.shown.matches(camera, settings, rw, rh))) {
        renderer.resize(rw, rh);
        panel.renderWidth = renderer.width();
        panel.renderHeight = renderer.height();
        renderer.record(cmd, camera, settings);
        loop.shown = ShownFrame{true, camera, settings, rw, rh};
        loop.frameInFlight = true;
        if (panel.playing) ++loop.framesRendered;
        if (panel.screenshotRequested) loop.pendingScreenshot = defaultScreenshotPath();
        if (options.frames && loop.framesRendered == *options.frames && !options.screenshot.empty())
            loop.pendingScreenshot = options.screenshot;
    }
    presenter.blitDisplay(renderer.display(), renderer.width(), renderer.height());
    panel.screenshotRequested = false;
}

}  // namespace

DebugView parseDebugView(const std::string& name) {
    if (std::optional<DebugView> view = debugViewFromName(name)) return *view;
    throw UsageError("--debug must be one of none, normals, albedo, depth, motion, samples, nodes, triangles, boxes, leaf-depth, leaf-triangles (got '" +
                     name + "')");
}

std::string cameraLine(const Camera& camera) {
    const Vec3 p = camera.position, d = normalize(camera.lookAt - camera.position);
    char line[256];
    std::snprintf(line, sizeof line, "camera %.6g,%.6g,%.6g direction %.6g,%.6g,%.6g", double(p.x), double(p.y),
                  double(p.z), double(d.x), double(d.y), double(d.z));
    return line;
}

void runViewer(Scene scene, const ViewerOptions& options) {
    ViewSettings settings = options.view;
    settings.apertureRadius = scene.camera.apertureRadius;
    settings.focusDistance = scene.camera.focusDistance;
    settings.samplesPerFrame = options.samplesPerFrame;
    settings.denoise = options.denoise;
    settings.antiAliasing = options.antiAliasing;
    settings.preview = options.preview;
    settings.debug = options.debug;
    prepareSceneSettings(scene, settings);

    Window window(options.width, options.height, "penumbra - " + scene.name);
    gpu::ContextOptions ctxOptions;
    ctxOptions.deviceSelector = options.device;
    ctxOptions.instanceExtensions = Window::requiredInstanceExtensions();
    ctxOptions.createSurface = [&](VkInstance instance) { return window.createSurface(instance); };
    gpu::ContextResult result = gpu::Context::create(ctxOptions);
    if (!result.context) throw Error(result.error);
    gpu::Context& ctx = *result.context;

    InteractiveRenderer renderer(ctx, scene, true, 1, options.bvhBuild);
    renderer.setCullBackfaces(options.cullBackfaces);
    Presenter presenter(ctx, window, options.vsync);
    UiLayer ui(ctx, window.get(), presenter);
    LoopState loop(scene, options, renderer);
    installCallbacks(window.get(), loop.input);
    auto last = std::chrono::steady_clock::now();

    while (!window.shouldClose()) {
        // Paused: sleep until something happens (no fan noise); playing: just poll.
        if (loop.panel.playing) glfwPollEvents();
        else glfwWaitEventsTimeout(0.1);
        auto now = std::chrono::steady_clock::now();
        const float dt = std::min(std::chrono::duration<float>(now - last).count(), 0.25f);
        last = now;
        const float step = options.fixedDt ? float(*options.fixedDt) : dt;  // simulated seconds this frame
        // Automation: after the N-th frame (or once a script ended the Doom level) nothing moves or
        // renders; its frame finishes, then exit.
        const bool automationDone =
            (options.frames && loop.framesRendered >= *options.frames) || loop.levelEndedByScript;

        applyInput(loop, scene, renderer, ui, window.get(), settings, step, automationDone);
        drawUi(loop, scene, renderer, ui, settings, dt);
        presenter.setVsync(loop.panel.vsync);
        if (!presenter.beginFrame()) {
            ImGui::EndFrame();
            continue;
        }
        finishShownFrame(loop, ctx, renderer);  // the previous frame has finished
        if (automationDone && !loop.frameInFlight) window.requestClose();
        VkCommandBuffer cmd = presenter.commandBuffer();
        renderOrShow(loop, cmd, renderer, presenter, window.framebufferSize(), settings, options, automationDone);
        presenter.beginUi();
        ui.render(cmd);
        presenter.endFrame();
    }
    presenter.waitIdle();
    if (options.printCamera) {
        std::printf("%s\n", cameraLine(loop.camera()).c_str());
        std::fflush(stdout);
    }
}

}  // namespace penumbra::viewer

namespace penumbra::viewer {
namespace {

void applyEdits(Scene& scene, InteractiveRenderer& renderer, ViewSettings& settings, EditState& edit,
                const EditRequests& requests, Navigation& nav, PanelState& panel) {
    if (requests.clearSelection) edit.object = edit.group = kNoObject;
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
        const bool lightValid = edit.lightChoice >= 0 && std::size_t(edit.lightChoice) < edit.lights.size();
        if (requests.lightChosen && lightValid) edit.light = lightParams(scene, edit.lights[edit.lightChoice]);
        if (requests.lightChanged && lightValid) {
            setLightParams(scene, edit.lights[edit.lightChoice], edit.light);
            edit.light = lightParams(scene, edit.lights[edit.lightChoice]);  // as clamped
            renderer.rebuildScene(scene, true);
        }
        if (requests.turnGroup && edit.group < scene.sphereGroups.size()) {
            turnSphereGroup(scene, edit.group, Affine::eulerDegrees(edit.turnDegrees));
            edit.turnDegrees = Vec3{0};
            renderer.rebuildScene(scene, true);
        }
        if (requests.moveObject && edit.group < scene.sphereGroups.size()) {
            moveSphereGroup(scene, edit.group, edit.position - sphereGroupPivot(scene, edit.group));
            renderer.rebuildScene(scene, true);
        } else if (requests.moveObject && isObject(scene, edit.object)) {
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
            prepareSceneSettings(next, nextSettings);
            renderer.rebuildScene(next, true);
            scene = std::move(next);
            settings = nextSettings;
            settings.apertureRadius = scene.camera.apertureRadius;
            settings.focusDistance = scene.camera.focusDistance;
            nav = Navigation(scene, false);  // the new scene's own movement mode
            panel.hasPhantom = nav.hasPhantom();
            panel.phantom = true;
            edit.object = edit.group = kNoObject;
            loadLights(scene, edit);
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
