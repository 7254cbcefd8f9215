#include "app/viewer/ui_panel.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <cstdio>

#include "app/viewer/presenter.h"
#include "gpu/check.h"
#include "gpu/commands.h"

namespace penumbra::viewer {
namespace {

void checkImguiVk(VkResult result) {
    if (result != VK_SUCCESS) gpu::throwVkError("ImGui Vulkan backend", result, __FILE__, __LINE__);
}

// The heat ramp of shaders/tonemap.comp, for the legend.
ImU32 heatColor(float t) {
    auto band = [&](float c) { return std::min(std::max(1.5f - std::abs(4.0f * t - c), 0.0f), 1.0f); };
    return ImGui::GetColorU32(ImVec4(band(3.0f), band(2.0f), band(1.0f), 1.0f));
}

void heatLegend(const char* what, std::uint32_t maximum) {
    ImGui::Text("%s: 0", what);
    ImGui::SameLine();
    ImVec2 p = ImGui::GetCursorScreenPos();
    const float width = 160, height = ImGui::GetTextLineHeight();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const int steps = 32;
    for (int i = 0; i < steps; ++i) {
        float x0 = p.x + width * float(i) / steps, x1 = p.x + width * float(i + 1) / steps;
        draw->AddRectFilled(ImVec2(x0, p.y), ImVec2(x1, p.y + height), heatColor((i + 0.5f) / steps));
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::SameLine();
    ImGui::Text("%u (max this frame)", maximum);
}

}  // namespace

UiLayer::UiLayer(const gpu::Context& ctx, GLFWwindow* window, const Presenter& presenter) : device_(ctx.device()) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 4;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    PN_VK(vkCreateDescriptorPool(ctx.device(), &poolInfo, nullptr, &pool));
    pool_ = gpu::DescriptorPool(ctx.device(), pool);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini dropped into the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window, true);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance();
    info.PhysicalDevice = ctx.physicalDevice();
    info.Device = ctx.device();
    info.QueueFamily = ctx.queueFamily();
    info.Queue = ctx.queue();
    info.DescriptorPool = pool;
    info.MinImageCount = presenter.minImageCount();
    info.ImageCount = std::max(presenter.imageCount(), presenter.minImageCount());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImguiVk;
    ImGui_ImplVulkan_Init(&info, presenter.renderPass());
    try {
        gpu::Commands commands(ctx);
        commands.run([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
        ImGui_ImplVulkan_DestroyFontUploadObjects();
    } catch (...) {  // a lost device or no memory: no destructor will run, so undo Init here
        shutdown();
        throw;
    }
}

UiLayer::~UiLayer() {
    // The presenter's last frame may still draw with ImGui's buffers (an exception in the frame
    // loop skips the wait for it, and the presenter, made first, goes last): wait for it before
    // they go. A lost device answers at once; the result changes nothing here.
    vkDeviceWaitIdle(device_);
    shutdown();
}

void UiLayer::shutdown() {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void UiLayer::newFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

bool UiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

void UiLayer::render(VkCommandBuffer cmd) {
    ImGui::Render();
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

namespace {

// Labels sit right of the widgets in this much room, so none is cut off (in font heights).
constexpr float kLabelEms = 15.5f;
constexpr float kPanelEms = 36.0f;  // the panel's width

void header(PanelState& state) {
    ImGui::TextWrapped("%s", state.sceneName.c_str());
    if (ImGui::Button(state.playing ? "Pause (P)" : "Play (P)")) state.playing = !state.playing;
    ImGui::SameLine();
    if (ImGui::Button("Screenshot (F12)")) state.screenshotRequested = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset camera (R)")) state.resetCamera = true;
    ImGui::Checkbox("vsync", &state.vsync);
    if (!state.playing) ImGui::TextDisabled("paused: showing one frame; Play renders continuously");
    if (state.walking)
        ImGui::TextDisabled(state.pointerCaptured ? "walking (F: fly); mouse captured, Esc releases it"
                                                  : "walking (F: fly); click the image to look with the mouse");
    else
        ImGui::TextDisabled(state.canWalk ? "free flight (F: walk)" : "free flight");
    if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
}

void display(ViewSettings& s, const PanelState& state, const ViewerStats& stats) {
    if (!ImGui::CollapsingHeader("Display")) return;
    ImGui::SliderFloat("exposure (stops)", &s.exposure, -8.0f, 8.0f);
    int curve = s.toneMapper == ToneMapper::Aces ? 1 : 0;
    if (ImGui::Combo("tone mapper", &curve, "Reinhard\0ACES\0")) s.toneMapper = curve ? ToneMapper::Aces : ToneMapper::Reinhard;
    int debug = int(s.debug);
    if (ImGui::Combo("debug view", &debug,
                     "image\0normals\0albedo\0depth\0motion\0sample count\0BVH nodes visited\0triangles tested\0"
                     "BVH boxes by depth\0BVH depth of the hit leaf\0primitives in the hit leaf\0"))
        s.debug = DebugView(debug);
    if (s.debug != DebugView::None && s.debug != DebugView::BvhBoxes) {
        ImGui::SliderFloat("debug opacity", &s.debugOpacity, 0.0f, 1.0f, "%.2f");
        ImGui::Checkbox("debug view in a small window", &s.debugInset);
    }
    if (s.debug == DebugView::HeatNodes) heatLegend("nodes", stats.heatMaxNodes);
    if (s.debug == DebugView::HeatTriangles) heatLegend("triangles", stats.heatMaxTriangles);
    if (s.debug == DebugView::LeafDepth) heatLegend("leaf depth", stats.heatMaxLeafDepth);
    if (s.debug == DebugView::LeafTriangles) heatLegend("leaf primitives", stats.heatMaxLeafTriangles);
    if (s.debug == DebugView::BvhBoxes) {
        int depth = int(s.boxDepth);
        if (ImGui::SliderInt("box depth (root: 1)", &depth, 1, std::max(int(state.bvhDepth), 1)))
            s.boxDepth = std::uint32_t(std::max(depth, 1));
        ImGui::SliderFloat("line width (px)", &s.boxLineWidth, 1.0f, 5.0f, "%.1f");
        ImGui::Text("at most %u boxes are drawn", PN_MAX_OVERLAY_BOXES);
    }
}

// The last frame's rays, and with counting on what they cost and found ("Casually Pathtracing with
// WebGPU" shows triangles hit and shadow rays that hit; render/ray_counters.h).
void rayStatistics(PanelState& state, const ViewerStats& stats) {
    ImGui::Checkbox("count tests and hits (slower kernels)", &state.frameStatistics);
    const auto n = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    if (!stats.frameStatistics) {
        ImGui::Text("rays: %llu closest-hit, %llu shadow", n(stats.closestRays), n(stats.shadowRays));
        return;
    }
    const double closest = double(std::max<std::uint64_t>(stats.closestRays, 1));
    const double shadow = double(std::max<std::uint64_t>(stats.shadowRays, 1));
    ImGui::Text("closest-hit rays %llu, %llu hit (%.1f%%)", n(stats.closestRays), n(stats.closestHits),
                100.0 * double(stats.closestHits) / closest);
    ImGui::Text("shadow rays %llu, %llu blocked (%.1f%%)", n(stats.shadowRays), n(stats.shadowBlocked),
                100.0 * double(stats.shadowBlocked) / shadow);
    ImGui::Text("primitives tested %llu (%.1f per ray)", n(stats.primitivesTested),
                double(stats.primitivesTested) / double(std::max<std::uint64_t>(stats.closestRays + stats.shadowRays, 1)));
}

void statistics(PanelState& state, const ViewerStats& stats) {
    if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Text("%.1f fps, render %ux%u", state.fps, state.renderWidth, state.renderHeight);
    ImGui::Text("accumulated: %u spp", stats.samplesPerPixel);
    ImGui::Text("%.2f Mrays/s", stats.raysPerSecond * 1e-6);
    rayStatistics(state, stats);
    for (std::uint32_t p = 0; p < std::uint32_t(ViewerPass::Count); ++p)
        if (stats.passMilliseconds[p] != 0)
            ImGui::Text("  %-9s %7.2f ms", viewerPassName(ViewerPass(p)), stats.passMilliseconds[p]);
    ImGui::Text("%zu triangles, %zu BVH nodes", state.triangles, state.bvhNodes);
    if (state.walking) ImGui::Text("walking at Doom's speed (Shift runs)");
    else ImGui::Text("flight speed %.2f m/s (scroll)", state.cameraSpeed);
}

}  // namespace

void UiLayer::drawPanel(ViewSettings& s, PanelState& state, const ViewerStats& stats, EditState& edit,
                        EditRequests& requests) {
    // As tall as its open sections, but never taller than the window (it scrolls inside then);
    // collapsible from its title bar, and Tab hides it.
    const float em = ImGui::GetFontSize();
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelEms * em, 0),
                                        ImVec2(kPanelEms * em, std::max(screen.y - 20, 8 * em)));
    ImGui::Begin("Penumbra (Tab hides this panel)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushItemWidth(-kLabelEms * em);
    header(state);

    if (ImGui::CollapsingHeader("Rendering", ImGuiTreeNodeFlags_DefaultOpen)) {
        int spp = int(s.samplesPerFrame), bounces = int(s.maxBounces);
        if (ImGui::SliderInt("spp per frame", &spp, 1, 64)) s.samplesPerFrame = std::uint32_t(spp);
        if (ImGui::SliderInt("max bounces", &bounces, 0, 32)) s.maxBounces = std::uint32_t(bounces);
        ImGui::SliderFloat("resolution scale", &s.resolutionScale, kResolutionScaleRange.min,
                           kResolutionScaleRange.max, "%.2f");
        ImGui::SliderFloat("texture saturation", &s.textureSaturation, kTextureSaturationRange.min,
                           kTextureSaturationRange.max, "%.2f");
        ImGui::SliderFloat("render distance (0: all)", &s.renderDistance, kRenderDistanceRange.min, kRenderDistanceRange.max,
                           "%.0f m");
        ImGui::Checkbox("one camera ray per pixel per frame", &s.shareCameraRays);
        ImGui::Checkbox("anti-aliasing (jitter camera rays over the pixel)", &s.antiAliasing);
        ImGui::Checkbox("fast preview while moving (V)", &s.preview);
        ImGui::SliderFloat("shadow-ray roulette below", &s.shadowRouletteShare, 0.0f, 0.5f, "%.2f of the pixel");
        ImGui::Checkbox("temporal accumulation", &s.temporal);
        ImGui::SliderFloat("history clamp (0: off)", &s.clampSigma, 0.0f, 4.0f, "%.2f sigma");
        ImGui::SliderFloat("max history (moving)", &s.maxHistory, 1.0f, 256.0f, "%.0f");
    }
    if (ImGui::CollapsingHeader("Denoiser")) {
        ImGui::Checkbox("a-trous denoiser", &s.denoise);
        int iterations = int(s.denoiseIterations);
        if (ImGui::SliderInt("iterations", &iterations, 1, 5)) s.denoiseIterations = std::uint32_t(iterations);
        ImGui::SliderFloat("luminance weight", &s.sigmaLuminance, 0.5f, 16.0f);
        ImGui::SliderFloat("normal weight", &s.sigmaNormal, 1.0f, 256.0f, "%.0f");
        ImGui::SliderFloat("depth weight", &s.sigmaDepth, 0.1f, 8.0f);
    }
    display(s, state, stats);
    if (state.hasTorch && ImGui::CollapsingHeader("Torch")) {
        ImGui::Checkbox("torch on", &s.torch);
        ImGui::ColorEdit3("colour", &s.torchColor.x);
        ImGui::SliderFloat("intensity (cd)", &s.torchIntensity, 0.0f, 1000.0f, "%.1f", ImGuiSliderFlags_Logarithmic);
        ImGui::SliderFloat("range (m, 0: none)", &s.torchRange, 0.0f, 100.0f);
    }
    if (state.hasPhantom) ImGui::Checkbox("phantom (H)", &state.phantom);
    drawEditSections(s, edit, requests);
    statistics(state, stats);
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace penumbra::viewer
