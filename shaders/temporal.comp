#version 460
// Temporal accumulation. With a still camera: the exact running mean of every frame's samples
// (N grows without bound, so the image converges to the one `penumbra render` makes). With a
// moving camera: history is fetched where the motion vector says this surface was, taps whose
// previous G-buffer shows another surface are rejected (disocclusion), the result is clamped to
// the current frame's neighbourhood in YCoCg, then blended with weight >= 1/maxHistory.
// Also writes the denoiser's input: illumination (radiance / albedo) and luminance variance.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"
#include "lib/pixel_estimate.glsl"

layout(std430, set = 0, binding = PN_BINDING_ACCUM) readonly buffer AccumBuffer { vec4 accum[]; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER_PREV) readonly buffer GBufferPrev { GBufferTexel gbufferPrev[]; };
layout(std430, set = 0, binding = PN_BINDING_HISTORY) readonly buffer HistoryIn { HistoryTexel history[]; };
layout(std430, set = 0, binding = PN_BINDING_HISTORY_OUT) writeonly buffer HistoryOut { HistoryTexel historyOut[]; };
layout(std430, set = 0, binding = PN_BINDING_PIXEL_ESTIMATES) writeonly buffer PixelEstimates { vec4 pixelEstimates[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_IN) writeonly buffer FilterIn { vec4 filterIn[]; };
layout(std430, set = 0, binding = PN_BINDING_DENOISE_GUIDE) writeonly buffer GuideOut { vec4 guide[]; };

// This frame's mean radiance at a pixel.
vec3 currentRadiance(uint i) { return accum[i].rgb / float(viewer.samplesPerFrame); }

// Is previous-frame texel `prev` the same surface as `g`, whose depth in the previous camera
// would be `expectedDepth`? Misses match misses.
bool sameSurface(GBufferTexel g, float expectedDepth, GBufferTexel prev) {
    if (g.surfaceId != prev.surfaceId) return false;
    if (g.surfaceId == 0u) return true;
    if (abs(expectedDepth - prev.depth) > viewer.depthTolerance * max(expectedDepth, 1e-6)) return false;
    return dot(g.normal, prev.normal) >= viewer.normalTolerance;
}

// The current frame's 3x3 neighbourhood in YCoCg: its mean and deviation, the clamp box, and the
// spatial variance used while a pixel has too little history for its own moments to mean anything.
void neighbourhood(ivec2 p, out vec3 mean, out vec3 sigma) {
    mean = vec3(0.0);
    vec3 meanSquares = vec3(0.0);
    float count = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (!insideImage(q)) continue;
            vec3 c = rgbToYCoCg(currentRadiance(pixelIndex(q)));
            mean += c;
            meanSquares += c * c;
            count += 1.0;
        }
    mean /= count;
    sigma = sqrt(max(meanSquares / count - mean * mean, vec3(0.0)));
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    float spp = float(viewer.samplesPerFrame);
    vec3 current = currentRadiance(i);
    float currentM1 = luminance(current);
    float currentM2 = accum[i].a / spp;
    GBufferTexel g = gbuffer[i];

    vec3 mean, sigma;
    neighbourhood(p, mean, sigma);

    bool haveHistory = false;
    HistoryTexel h;
    if (viewer.historyValid != 0u) {
        if (viewer.cameraMoved == 0u) {
            // Same pixel, same camera: only a changed surface (a moved object) breaks history.
            if (viewer.gbufferReused != 0u || sameSurface(g, g.depth, gbufferPrev[i])) {
                h = history[i];
                haveHistory = true;
            }
        } else {
            // Where this surface point was (it and the camera may both have moved), and its depth
            // in the previous camera then, for the tap test.
            vec2 centre = vec2(p) + 0.5;
            float expectedDepth = g.prevDepth;
            vec2 prevPos = centre + g.motion - 0.5;  // in texel-centre coordinates
            ivec2 base = ivec2(floor(prevPos));
            vec2 f = prevPos - vec2(base);
            h = HistoryTexel(vec3(0.0), 0.0, 0.0, 0.0, 0.0, 0.0);
            float weightSum = 0.0;
            for (int t = 0; t < 4; ++t) {
                ivec2 offset = ivec2(t & 1, t >> 1);
                ivec2 q = base + offset;
                float w = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
                if (w <= 0.0 || !insideImage(q)) continue;
                uint qi = pixelIndex(q);
                if (!sameSurface(g, expectedDepth, gbufferPrev[qi])) continue;
                HistoryTexel tap = history[qi];
                h.color += w * tap.color;
                h.samples += w * tap.samples;
                h.moment1 += w * tap.moment1;
                h.moment2 += w * tap.moment2;
                weightSum += w;
            }
            if (weightSum > 1e-3) {
                h.color /= weightSum;
                h.samples = min(h.samples / weightSum, viewer.maxHistory);
                h.moment1 /= weightSum;
                h.moment2 /= weightSum;
                if (viewer.clampSigma > 0.0) {
                    vec3 box = viewer.clampSigma * sigma;
                    h.color = max(yCoCgToRgb(clamp(rgbToYCoCg(h.color), mean - box, mean + box)), vec3(0.0));
                }
                haveHistory = true;
            }
        }
    }

    HistoryTexel o;
    o.pad1 = 0.0;
    if (haveHistory) {
        o.samples = h.samples + spp;
        float w = spp / o.samples;  // the running mean's 1/N, for spp samples at once
        o.color = h.color + (current - h.color) * w;
        o.moment1 = h.moment1 + (currentM1 - h.moment1) * w;
        o.moment2 = h.moment2 + (currentM2 - h.moment2) * w;
    } else {
        o = HistoryTexel(current, spp, currentM1, currentM2, 0.0, 0.0);
    }
    // Variance of the mean's luminance; from the neighbourhood while history is short (SVGF). The
    // denoiser's last pass weighs its output against the mean by it (atrous.comp).
    float variance = o.samples >= 4.0 * spp ? max(o.moment2 - o.moment1 * o.moment1, 0.0) / o.samples
                                            : sigma.x * sigma.x;
    o.meanVariance = variance;
    historyOut[i] = o;
    // The next frame's trace scales its shadow-ray roulette by this (lib/path.glsl).
    pixelEstimates[i] = vec4(pixelEstimateFromMoments(o.color, o.moment2, o.samples), 0.0);

    vec3 albedo = demodulationAlbedo(g);
    float albedoLuminance = max(luminance(albedo), 1e-3);
    filterIn[i] = vec4(o.color / albedo, variance / (albedoLuminance * albedoLuminance));
    // A reused G-buffer's guide is the one last frame wrote.
    if (viewer.gbufferReused == 0u)
        guide[i] = denoiseGuide(g.normal, g.surfaceId != 0u ? g.depth : 0.0, (g.flags & PN_GBUFFER_UNFILTERED) == 0u);
}
