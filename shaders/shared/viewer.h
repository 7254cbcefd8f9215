// The viewer's passes (G-buffer, history, temporal, a-trous, tonemap, debug views): their
// uniforms, per-pixel records, push constants and mode bits.
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_VIEWER_H
#define PENUMBRA_SHADER_VIEWER_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// ---- viewer passes (temporal.comp, atrous.comp, tonemap.comp, gbuffer.comp, heatmap.comp) ----
#define PN_TONEMAP_REINHARD 0u
#define PN_TONEMAP_ACES 1u
#define PN_DEBUG_NONE 0u
#define PN_DEBUG_NORMALS 1u
#define PN_DEBUG_ALBEDO 2u
#define PN_DEBUG_DEPTH 3u
#define PN_DEBUG_MOTION 4u
#define PN_DEBUG_SAMPLES 5u
#define PN_DEBUG_HEAT_NODES 6u   // BVH nodes visited by the primary ray
#define PN_DEBUG_HEAT_TRIS 7u    // triangles tested by the primary ray
#define PN_DEBUG_BVH_BOXES 8u    // the image with the BVH's boxes at one depth outlined (boxes.comp)
#define PN_DEBUG_LEAF_DEPTH 9u   // depth of the BVH leaf holding the primary ray's hit (root: 0)
#define PN_DEBUG_LEAF_TRIS 10u   // primitives in the BVH leaf holding the primary ray's hit
// The fast preview (ViewSettings::preview, shown while the view moves): the primary hit's albedo
// times the cosine between its normal and the ray, as a raster preview with a headlight draws it.
#define PN_DEBUG_PREVIEW 11u
#define PN_MAX_OVERLAY_BOXES 4096u  // boxes the overlay draws at most (each pixel tests every one)
// The debug view's small window (picture-in-picture): 1/PN_DEBUG_INSET_DIVISOR of the image's
// width and height, PN_DEBUG_INSET_MARGIN pixels from its bottom right corner, in a one-pixel frame.
#define PN_DEBUG_INSET_DIVISOR 4u
#define PN_DEBUG_INSET_MARGIN 8u
#define PN_OVERLAY_COLOR 0xff00ffffu  // RGBA8 of an outlined pixel: opaque yellow

#define PN_GBUFFER_SUBPIXEL 1u    // PassPush.mode bit of gbuffer.comp: trace cell passIndex of a 4x4 grid in the pixel
// GBufferTexel.flags bit: the pixel bypasses the a-trous filter (its raw mean is shown) and is no
// tap for its neighbours: a surface the camera sees emit (its light is not illumination times
// albedo, and blurring it spreads its glow; Doom's unseen sector light does not count), a window
// onto the sky, a sprite (a card whose texture's cut-out edges no normal or depth guide sees).
// The sky bypasses too, as any pixel whose primary ray missed.
#define PN_GBUFFER_UNFILTERED 1u
#define PN_ATROUS_LAST 1u        // PassPush.mode bit: the last a-trous pass multiplies the albedo back
#define PN_ATROUS_DISPLAY 2u     // PassPush.mode bit: ... and tone-maps it into the display (no debug view over it)
// PassPush.mode bit: ... and shows the filter alone, not weighed against the running mean (atrous.comp's
// blendWithMean), which never converges at rest: for measurements and tests of what the blend keeps.
#define PN_ATROUS_FILTER_ONLY 4u
// The denoiser's per-pixel guide, written by temporal.comp: xyz = the shading normal, w = the
// linear depth (0: the primary ray missed). 16 bytes instead of a 48-byte GBufferTexel per tap
// keeps the 25-tap filter in cache; plain floats rather than an 8-byte octahedral normal, because
// decoding (a normalize) at every tap cost more than the bytes (18% of the filter on the H200).
#define PN_DENOISE_GUIDE_BYTES 16u

// What the primary ray saw at a pixel's centre, 48 bytes.
PN_STRUCT(GBufferTexel) {
    vec3 normal;     // shading normal, unit, facing the camera; zero where the ray missed
    float depth;     // linear depth (distance along cameraForward); 0 where the ray missed
    vec3 albedo;     // textured base colour at the hit, what the denoiser divides out
    uint surfaceId;  // material + 1 (0: miss); a change at a pixel means a different surface
    vec2 motion;     // pixels from here to where the same point was in the previous frame (camera and object motion)
    float prevDepth; // the point's linear depth in the previous frame's camera, where it was then (0: miss)
    uint flags;      // PN_GBUFFER_* bits
};
#ifdef __cplusplus
static_assert(sizeof(GBufferTexel) == 48 && offsetof(GBufferTexel, depth) == 12 &&
              offsetof(GBufferTexel, albedo) == 16 && offsetof(GBufferTexel, surfaceId) == 28 &&
              offsetof(GBufferTexel, motion) == 32 && offsetof(GBufferTexel, flags) == 44);
#endif

// Push constants of the box overlay (boxes.comp), 16 bytes.
PN_STRUCT(BoxOverlayPush) {
    uint boxCount;    // boxes in the overlay buffer, at most PN_MAX_OVERLAY_BOXES
    float lineWidth;  // pixels: a pixel centre this close to a projected box edge is outlined
    uint pad0;
    uint pad1;
};
#ifdef __cplusplus
static_assert(sizeof(BoxOverlayPush) == 16 && offsetof(BoxOverlayPush, lineWidth) == 4);
#endif

// The temporal accumulation of one pixel, 32 bytes.
PN_STRUCT(HistoryTexel) {
    vec3 color;     // running mean of radiance
    float samples;  // N of the running mean (capped while the camera moves)
    float moment1;  // running mean of per-sample luminance
    float moment2;  // running mean of per-sample squared luminance (variance = m2 - m1^2)
    float meanVariance;  // variance of `color`'s luminance as an estimate (written for the denoiser; never read back)
    float pad1;
};
#ifdef __cplusplus
static_assert(sizeof(HistoryTexel) == 32 && offsetof(HistoryTexel, samples) == 12 &&
              offsetof(HistoryTexel, moment1) == 16 && offsetof(HistoryTexel, moment2) == 20 &&
              offsetof(HistoryTexel, meanVariance) == 24);
#endif

// Settings of the viewer's passes (uniform buffer), 128 bytes. The previous camera is what
// reprojection projects into: it plays the role of the previous view-projection matrix.
PN_STRUCT(ViewerUniforms) {
    vec3 prevCameraPosition;
    float prevTanHalfFovY;
    vec3 prevCameraRight;
    float prevAspect;
    vec3 prevCameraUp;
    uint historyValid;     // 0: no usable history (first frame, reset, lighting changed)
    vec3 prevCameraForward;
    uint cameraMoved;      // 0: exact running mean; else reproject, reject, clamp and blend
    float exposure;        // stops
    uint toneMapper;       // PN_TONEMAP_*
    uint debugMode;        // PN_DEBUG_*
    uint samplesPerFrame;  // paths per pixel the trace pass added this frame
    float clampSigma;      // history is clamped to the neighbourhood's mean +- clampSigma * sigma (0: off)
    float depthTolerance;  // relative depth difference above which history is disoccluded
    float normalTolerance; // cosine below which history is disoccluded
    float maxHistory;      // cap on N while moving: the blend weight never falls below 1/maxHistory
    float sigmaLuminance;  // a-trous edge stopping: luminance, in standard deviations
    float sigmaNormal;     // exponent on the normals' cosine
    float sigmaDepth;      // relative depth difference per pixel of step
    float heatMax;         // heat-map count shown as the hottest colour
    uint denoise;          // nonzero: the tonemap input is the denoiser's output
    float debugOpacity;    // the debug view blended over the image: 1 shows only the view, 0 only the image
    uint debugInset;       // nonzero: the debug view in a small window over the image (PN_DEBUG_INSET_*)
    uint gbufferReused;    // nonzero: both G-buffers hold this still view (last frame's guide stands too)
};
#ifdef __cplusplus
static_assert(sizeof(ViewerUniforms) == 128 && offsetof(ViewerUniforms, prevTanHalfFovY) == 12 &&
              offsetof(ViewerUniforms, prevCameraRight) == 16 && offsetof(ViewerUniforms, prevAspect) == 28 &&
              offsetof(ViewerUniforms, prevCameraUp) == 32 && offsetof(ViewerUniforms, historyValid) == 44 &&
              offsetof(ViewerUniforms, prevCameraForward) == 48 && offsetof(ViewerUniforms, cameraMoved) == 60 &&
              offsetof(ViewerUniforms, exposure) == 64 && offsetof(ViewerUniforms, samplesPerFrame) == 76 &&
              offsetof(ViewerUniforms, clampSigma) == 80 && offsetof(ViewerUniforms, maxHistory) == 92 &&
              offsetof(ViewerUniforms, sigmaLuminance) == 96 && offsetof(ViewerUniforms, heatMax) == 108 &&
              offsetof(ViewerUniforms, denoise) == 112 && offsetof(ViewerUniforms, debugOpacity) == 116 &&
              offsetof(ViewerUniforms, debugInset) == 120);
#endif

// Largest counts of a heat-map frame (for the legend), 16 bytes. heatmap.comp writes a pixel's
// own counts as a vec4 (nodes, triangles, leaf depth, leaf primitives; the last two 0 on a miss).
PN_STRUCT(HeatCounters) {
    uint maxNodes;
    uint maxTris;
    uint maxLeafDepth;
    uint maxLeafTris;
};
#ifdef __cplusplus
static_assert(sizeof(HeatCounters) == 16 && offsetof(HeatCounters, maxLeafDepth) == 8 &&
              offsetof(HeatCounters, maxLeafTris) == 12);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
