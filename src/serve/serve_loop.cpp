#include "serve/serve_loop.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

#include "interact/navigation.h"
#include "interact/object_drag.h"
#include "interact/play_step.h"
#include "render/interactive_renderer.h"
#include "render/picking.h"
#include "scene/animation.h"
#include "scene/objects.h"
#include "serve/browser_input.h"
#include "serve/remote_settings.h"

namespace penumbra::serve {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kStatsInterval = std::chrono::milliseconds(250);
constexpr const char* kControls =
    "WASD/arrows move, Q/E turn, Space/C up/down, Space/Enter use (walking a Doom level), Shift fast, F walk/fly, "
    "G grid, R reset, P play/pause, H phantom, "
    "N next object, I/K/J/L/O/U and ,/. move and turn it, click selects, drag moves (Shift turns)";

// What the loop carries from frame to frame besides the scene and the renderer.
struct LoopState {
    LoopState(const Scene& scene, const ServeOptions& options) : nav(scene, options.fly), pacer(options.pace) {
        remote.view = options.view;
        remote.phantom = options.phantom;
    }
    viewer::Navigation nav;
    FramePacer pacer;
    RemoteState remote;
    BrowserInput input;
    std::map<std::uint64_t, std::uint32_t> appliedSeq;  // each browser's latest input applied
    std::uint32_t selectedInstance = kNoObject;
    std::optional<viewer::ObjectDrag> drag;
    std::uint64_t dragOwner = 0;
    std::string message;
    double animationClock = 0;
    std::uint32_t frameNumber = 0;
    bool mustRender = true;  // a browser joined or something changed: render even when paused
    bool instancesMoved = false;
    bool geometryChanged = false;  // a mesh moved (WorldChange): the renderer rebuilds the scene
    std::vector<std::uint32_t> lightsChanged;  // materials whose emission a Doom light special changed
    std::vector<std::uint32_t> materialsChanged;  // a Doom switch's or key's material (textures, cutoff)
    std::optional<Camera> shownCamera;
    std::optional<ViewSettings> shownSettings;
};

// The renderer's picture size at the current resolution scale.
std::pair<std::uint32_t, std::uint32_t> pictureSize(const ServeOptions& o, const ViewSettings& v) {
    return {scaledSide(o.width, v.resolutionScale), scaledSide(o.height, v.resolutionScale)};
}

void select(LoopState& s, const Scene& scene, const InteractiveRenderer& renderer, const ClickMessage& click) {
    const std::uint32_t w = renderer.width(), h = renderer.height();
    const Pick pick = pickPixel(renderer.sceneArrays(), s.nav.camera(), w, h, click.x * float(w), click.y * float(h));
    s.selectedInstance = pick.instance;
    if (pick.instance < scene.instances.size()) s.message = instanceName(scene, pick.instance) + viewer::kInstanceControls;
    else if (isObject(scene, pick.object)) s.message = objectName(scene, pick.object);
    else s.message = "nothing selected";
}

void applyMessage(LoopState& s, Scene& scene, const InteractiveRenderer& renderer, std::uint64_t client,
                  const ClientMessage& m) {
    const float w = float(renderer.width()), h = float(renderer.height());
    viewer::InputState& in = s.input.of(client);
    if (const auto* key = std::get_if<KeyMessage>(&m.body)) {
        viewer::applyKey(in, key->key, key->down);
    } else if (const auto* look = std::get_if<LookMessage>(&m.body)) {
        viewer::applyLook(in, look->dx, look->dy);
    } else if (const auto* wheel = std::get_if<WheelMessage>(&m.body)) {
        in.scroll += wheel->notches;
    } else if (const auto* click = std::get_if<ClickMessage>(&m.body)) {
        select(s, scene, renderer, *click);
    } else if (const auto* grab = std::get_if<GrabMessage>(&m.body)) {
        s.drag = viewer::grabInstance(scene, renderer.sceneArrays(), s.nav.camera(), renderer.width(),
                                      renderer.height(), grab->x * w, grab->y * h, s.selectedInstance, grab->turn);
        s.dragOwner = client;
    } else if (const auto* drag = std::get_if<DragMessage>(&m.body)) {
        if (s.drag && s.dragOwner == client &&
            viewer::followCursor(*s.drag, scene, s.nav.camera(), renderer.width(), renderer.height(), drag->x * w,
                                 drag->y * h))
            s.instancesMoved = true;
    } else if (std::holds_alternative<ReleaseMessage>(m.body)) {
        if (s.dragOwner == client) s.drag.reset();
    } else if (const auto* set = std::get_if<SetMessage>(&m.body)) {
        std::string error;
        if (!applySetting(s.remote, set->name, set->value, error)) logDropped("a setting: " + error);
    }
}

void applyInbox(LoopState& s, Scene& scene, const InteractiveRenderer& renderer, std::vector<InboxItem> items) {
    for (InboxItem& item : items) {
        if (item.kind == InboxItem::Kind::Joined) {
            s.mustRender = true;  // the newcomer needs a picture, paused or not
        } else if (item.kind == InboxItem::Kind::Left) {
            s.input.remove(item.client);
            s.appliedSeq.erase(item.client);
            if (s.dragOwner == item.client) s.drag.reset();
        } else {
            if (item.message.seq != 0) s.appliedSeq[item.client] = std::max(s.appliedSeq[item.client], item.message.seq);
            applyMessage(s, scene, renderer, item.client, item.message);
        }
    }
}

// The merged input moves the camera, the selected instance and the clock, as the viewer's does.
void applyInput(LoopState& s, Scene& scene, float step) {
    const viewer::InputState in = s.input.merged();
    if (in.pauseToggled) s.remote.playing = !s.remote.playing;
    if (std::string line = s.nav.handlePresses(in, scene); !line.empty()) s.message = line;
    if (in.nextInstance && !scene.instances.empty()) {
        s.selectedInstance = s.selectedInstance + 1 < scene.instances.size() ? s.selectedInstance + 1 : 0;
        s.message = instanceName(scene, s.selectedInstance) + viewer::kInstanceControls;
    }
    if (viewer::moveSelectedInstance(scene, s.selectedInstance, viewer::objectInputFrom(in), s.nav.camera(),
                                     s.nav.speed(), step))
        s.instancesMoved = true;
    // The phantom's switch (H or the page's checkbox), paused or playing.
    if (in.phantomToggled) s.remote.phantom = !s.remote.phantom;
    if (s.nav.showPhantom(scene, s.remote.phantom, s.animationClock)) s.instancesMoved = true;
    if (s.remote.playing) {
        const viewer::WorldChange change = viewer::playStep(scene, s.nav, in, s.animationClock, step);
        s.lightsChanged.insert(s.lightsChanged.end(), change.lightsChanged.begin(), change.lightsChanged.end());
        s.materialsChanged.insert(s.materialsChanged.end(), change.materialsChanged.begin(),
                                  change.materialsChanged.end());
        if (change.levelCompleted) {
            std::printf("%s\n", change.levelCompleted->c_str());
            std::fflush(stdout);
            s.message = *change.levelCompleted;
        }
        s.remote.view.time = float(s.animationClock);
        if (change.instancesMoved || change.geometryChanged) s.instancesMoved = true;
        s.geometryChanged = s.geometryChanged || change.geometryChanged;
    }
    s.input.endFrame();
}

nlohmann::json vec(Vec3 v) { return {v.x, v.y, v.z}; }

nlohmann::json helloJson(const LoopState& s, const Scene& scene, const InteractiveRenderer& r, const ServeOptions& o) {
    return {{"t", "hello"},          {"scene", scene.name},         {"width", o.width},
            {"height", o.height},    {"settings", settingsJson(s.remote)}, {"debugViews", debugViewsJson()},
            {"ranges", settingRangesJson()},
            {"walking", s.nav.walking()}, {"canWalk", s.nav.canWalk()}, {"hasTorch", r.hasTorch()},
            {"hasPhantom", s.nav.hasPhantom()},
            {"controls", kControls}};
}

nlohmann::json statsJson(const LoopState& s, const InteractiveRenderer& r, const ClientHub& hub,
                         const FrameEncoder& encoder, double renderedFps) {
    const Camera camera = s.nav.camera();
    return {{"t", "stats"},
            {"renderMs", r.stats().passMilliseconds[std::size_t(ViewerPass::Frame)]},
            {"encodeMs", encoder.lastEncodeMs()},
            {"renderedFps", renderedFps},
            {"spp", r.stats().samplesPerPixel},
            {"width", r.width()},
            {"height", r.height()},
            {"clients", hub.clients()},
            {"walking", s.nav.walking()},
            {"playing", s.remote.playing},
            {"settings", settingsJson(s.remote)},
            {"message", s.message},
            {"camera", vec(camera.position)},
            {"lookAt", vec(camera.lookAt)}};
}

// Renders one frame, and copies it for the encoder when the encoder will want it.
void renderFrame(LoopState& s, const Scene& scene, InteractiveRenderer& renderer, FrameReadback& readback,
                 const Camera& camera, double frameSeconds) {
    const auto now = Clock::now();
    if (s.shownCamera != camera || s.instancesMoved) s.pacer.noteMotion(now);
    if (s.geometryChanged) renderer.rebuildScene(scene, true);
    else if (s.instancesMoved) renderer.setInstanceTransforms(scene);
    FrameMeta meta{++s.frameNumber, renderer.width(), renderer.height(), 0, s.pacer.moving(now), {}};
    meta.acks.assign(s.appliedSeq.begin(), s.appliedSeq.end());
    const bool copy = s.pacer.takeFrame(now, frameSeconds) || s.mustRender;
    bool copied = false;
    renderer.commands().run([&](VkCommandBuffer cmd) {
        renderer.record(cmd, camera, s.remote.view);
        if (copy) copied = readback.recordCopy(cmd, renderer.display(), std::move(meta));
    });
    renderer.finishFrame();
    if (copied) readback.publish(float(renderer.stats().passMilliseconds[std::size_t(ViewerPass::Frame)]));
    s.shownCamera = camera;
    s.shownSettings = s.remote.view;
    s.mustRender = s.instancesMoved = s.geometryChanged = false;
}

}  // namespace

struct ServeLoop::State {
    State(const gpu::Context& ctx, Scene& sceneToShow, const ServeOptions& o, ClientHub& h)
        : scene(sceneToShow), options(o), hub(h), renderer(ctx, sceneToShow, true), loop(sceneToShow, o) {}
    Scene& scene;
    const ServeOptions& options;
    ClientHub& hub;
    InteractiveRenderer renderer;
    LoopState loop;
};

ServeLoop::ServeLoop(const gpu::Context& ctx, Scene& scene, const ServeOptions& options, ClientHub& hub)
    : state_(std::make_unique<State>(ctx, scene, options, hub)) {
    hub.setHello(helloJson(state_->loop, scene, state_->renderer, options));
}

ServeLoop::~ServeLoop() = default;

void ServeLoop::run(FrameReadback& readback, FrameEncoder& encoder, const std::function<bool()>& stopRequested) {
    Scene& scene = state_->scene;
    const ServeOptions& options = state_->options;
    ClientHub& hub = state_->hub;
    InteractiveRenderer& renderer = state_->renderer;
    LoopState& s = state_->loop;
    auto last = Clock::now(), lastStats = last;
    double frameSeconds = 0.005, renderedFps = 0;
    std::uint32_t framesSinceStats = 0;
    while (!stopRequested()) {
        if (hub.clients() == 0 && !hub.waitForClient(std::chrono::milliseconds(100))) {
            applyInbox(s, scene, renderer, hub.drain());  // browsers that came and went
            last = Clock::now();  // nobody watches: render nothing, and no time passes
            continue;
        }
        const auto now = Clock::now();
        const float step = std::min(std::chrono::duration<float>(now - last).count(), 0.25f);
        last = now;
        const auto [w, h] = pictureSize(options, s.remote.view);
        renderer.resize(w, h);
        applyInbox(s, scene, renderer, hub.drain());
        applyInput(s, scene, step);
        for (std::uint32_t m : s.lightsChanged) renderer.setUnsampledEmission(m, scene.materials[m].emission);
        s.lightsChanged.clear();
        for (std::uint32_t m : s.materialsChanged) renderer.setMaterial(m, scene.materials[m]);
        s.materialsChanged.clear();
        const Camera camera = s.nav.camera();
        const bool changed = s.shownCamera != camera || s.shownSettings != s.remote.view || s.instancesMoved;
        if (s.remote.playing || s.mustRender || changed) {
            renderFrame(s, scene, renderer, readback, camera, frameSeconds);
            ++framesSinceStats;
            frameSeconds = 0.9 * frameSeconds + 0.1 * std::chrono::duration<double>(Clock::now() - now).count();
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));  // paused and still: nothing to draw
        }
        if (Clock::now() - lastStats >= kStatsInterval) {
            renderedFps = framesSinceStats / std::chrono::duration<double>(Clock::now() - lastStats).count();
            lastStats = Clock::now();
            framesSinceStats = 0;
            hub.setHello(helloJson(s, scene, renderer, options));
            hub.broadcastStats(statsJson(s, renderer, hub, encoder, renderedFps));
        }
    }
}

}  // namespace penumbra::serve
