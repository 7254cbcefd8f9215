// What the viewer's panel controls: everything that changes how a frame is made or shown.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include "core/vec.h"
#include "render/settings.h"
#include "shared/types.h"

namespace penumbra {

enum class ToneMapper : std::uint32_t { Reinhard = PN_TONEMAP_REINHARD, Aces = PN_TONEMAP_ACES };

enum class DebugView : std::uint32_t {
    None = PN_DEBUG_NONE,
    Normals = PN_DEBUG_NORMALS,
    Albedo = PN_DEBUG_ALBEDO,
    Depth = PN_DEBUG_DEPTH,
    Motion = PN_DEBUG_MOTION,
    Samples = PN_DEBUG_SAMPLES,
    HeatNodes = PN_DEBUG_HEAT_NODES,
    HeatTriangles = PN_DEBUG_HEAT_TRIS,
    BvhBoxes = PN_DEBUG_BVH_BOXES,  // the image, with the BVH's boxes at boxDepth outlined
    LeafDepth = PN_DEBUG_LEAF_DEPTH,
    LeafTriangles = PN_DEBUG_LEAF_TRIS,
};

// The debug views by the names --debug and the browser's panel give them, "none" first.
std::span<const std::pair<const char*, DebugView>> debugViewNames();
std::optional<DebugView> debugViewFromName(std::string_view name);
const char* debugViewName(DebugView view);

// The ranges of the settings the panel, the command line (view, serve) and the browser's page
// offer: one place, so the three agree.
struct SettingRange {
    float min, max;
};
// Of the window's size. Above 1 the frame is rendered larger and filtered down to the window
// (supersampling: at 2, each window pixel averages 2x2 rendered ones).
inline constexpr SettingRange kResolutionScaleRange{0.25f, 2.0f};
// Of base-colour textures: 0 grey, 1 as they are, 2 twice as far from grey (shared/view_limits.h).
inline constexpr SettingRange kTextureSaturationRange{0.0f, 2.0f};
// Metres across the floor from the camera beyond which nothing is drawn; 0: no limit.
inline constexpr SettingRange kRenderDistanceRange{0.0f, 500.0f};

// The render's side for a window side at `scale` (clamped to kResolutionScaleRange), at least 1.
std::uint32_t scaledSide(std::uint32_t side, float scale);

struct ViewSettings;
// UsageError naming the flag of the first setting outside its range (the command line's check;
// the panel and the page clamp instead).
void checkViewSettingRanges(const ViewSettings& settings);

struct ViewSettings {
    std::uint32_t samplesPerFrame = 1;
    std::uint32_t maxBounces = 8;
    // Russian roulette may end paths from this bounce on. Earlier starts make frames faster but
    // noisier per unit of time on most scenes (docs/PERFORMANCE.md, "Equal-time error"); a scene
    // may ask for another start (Scene::viewerRouletteStart: Doom levels use 2).
    std::uint32_t rouletteStart = 3;
    // A pixel's samples in a frame share one camera ray, which the wavefront traces once instead of
    // once per sample; frames move it over the pixel (shared/pass_jitter.h). Faster at several
    // samples per frame (DOOM1 E1M1 1280x800 x 4: 0.25 ms of 4.74), and the denoised image is as
    // good or better at equal time, but the raw mean can be noisier where textures have detail
    // below a pixel (Freedoom E1M1: +6%), so it is off unless asked for.
    bool shareCameraRays = false;
    bool antiAliasing = true;  // RenderSettings::pixelJitter
    // Fast preview: while the view moves, frames show the primary hits' albedo times a cosine (the
    // G-buffer and the display pass, no path tracing); the first still frame restarts the mean.
    bool preview = false;
    // RenderSettings::shadowRouletteShare: scaled by the history's mean, so it acts once a pixel's
    // history holds PN_PIXEL_ESTIMATE_MIN_SAMPLES samples.
    float shadowRouletteShare = kDefaultShadowRouletteShare;
    float resolutionScale = 1.0f;  // render at this multiple of the window (kResolutionScaleRange)
    bool temporal = true;
    bool denoise = false;
    std::uint32_t denoiseIterations = 5;
    // Off: the a-trous filter's output alone, which keeps a bias at rest that no number of frames
    // removes; on (the default): weighed against the running mean, to which a still view converges
    // (shaders/atrous.comp, blendWithMean). Off is for measurements (`bench --denoise-filter-only`).
    bool denoiseConverges = true;
    float sigmaLuminance = 4.0f;
    float sigmaNormal = 128.0f;
    float sigmaDepth = 1.0f;
    float clampSigma = 1.5f;
    float maxHistory = 32.0f;  // samples kept while the camera moves
    float exposure = 0.0f;     // stops
    ToneMapper toneMapper = ToneMapper::Reinhard;
    DebugView debug = DebugView::None;
    float debugOpacity = 1.0f;  // of the debug view over the image: 1 shows only the view, 0 only the image
    bool debugInset = false;    // the debug view in a small window over the image (picture-in-picture)
    std::uint32_t boxDepth = 1;   // BvhBoxes: the BVH depth whose boxes are outlined (root: 1)
    float boxLineWidth = 1.5f;    // BvhBoxes: pixels
    // Depth of field, overriding the camera's own (a thin lens; radius 0 is a pinhole).
    float apertureRadius = 0.0f;  // metres
    float focusDistance = 0.0f;   // metres along the view direction; 0: the camera's look-at distance
    // The camera torch (a point light moved with the camera each frame).
    bool torch = false;
    Vec3 torchColor{1.0f, 0.85f, 0.6f};
    float torchIntensity = 80.0f;  // candela
    float torchRange = 0.0f;       // 0: unlimited
    float time = 0.0f;             // seconds: the moment animated textures show (advanced while playing)
    float textureSaturation = 1.0f;  // kTextureSaturationRange (RenderSettings::textureSaturation)
    float renderDistance = 0.0f;     // metres, kRenderDistanceRange; 0: no limit

    bool operator==(const ViewSettings&) const = default;
};

}  // namespace penumbra
