#version 460
// Display: exposure, a tone curve and sRGB encoding of the temporal (or denoised) radiance, and a
// debug view blended over it (over the whole image or in a small window), packed as RGBA8 for the
// copy to the window (lib/display.glsl). When the denoiser runs and no debug view is drawn, its
// last pass writes the display itself and this pass is not recorded.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"
#include "lib/display.glsl"

layout(std430, set = 0, binding = PN_BINDING_HISTORY_OUT) readonly buffer HistoryBuffer { HistoryTexel history[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) readonly buffer FilteredBuffer { vec4 filtered[]; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_DISPLAY) writeonly buffer DisplayBuffer { uint display[]; };

// Blue (0) through green and yellow to red (1): the heat-map legend uses the same ramp.
vec3 heatRamp(float t) {
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

// The fast preview's shading: albedo times the cosine at the pixel-centre hit (black on a miss).
vec3 previewColor(uint i, GBufferTexel g) {
    if (g.surfaceId == 0u) return vec3(0.0);
    vec2 centre = vec2(float(i % frame.width), float(i / frame.width)) + 0.5;
    return g.albedo * abs(dot(g.normal, normalize(viewDirection(centre))));
}

// Debug views are display colours already (no tone curve), in linear light.
vec3 debugColor(uint i) {
    GBufferTexel g = gbuffer[i];
    switch (viewer.debugMode) {
        case PN_DEBUG_PREVIEW: return previewColor(i, g);
        case PN_DEBUG_NORMALS: return g.surfaceId == 0u ? vec3(0.0) : g.normal * 0.5 + 0.5;
        case PN_DEBUG_ALBEDO: return g.albedo;
        case PN_DEBUG_DEPTH: return vec3(g.depth > 0.0 ? 1.0 / (1.0 + g.depth) : 0.0);
        case PN_DEBUG_MOTION: return vec3(min(abs(g.motion) * 0.1, vec2(1.0)), 0.0);
        case PN_DEBUG_SAMPLES: return heatRamp(history[i].samples / max(viewer.heatMax, 1.0));
        case PN_DEBUG_HEAT_NODES: return heatRamp(filtered[i].x / max(viewer.heatMax, 1.0));
        case PN_DEBUG_HEAT_TRIS: return heatRamp(filtered[i].y / max(viewer.heatMax, 1.0));
        // Leaf views: black where the ray missed (no leaf).
        case PN_DEBUG_LEAF_DEPTH:
            return filtered[i].w == 0.0 ? vec3(0.0) : heatRamp(filtered[i].z / max(viewer.heatMax, 1.0));
        case PN_DEBUG_LEAF_TRIS:
            return filtered[i].w == 0.0 ? vec3(0.0) : heatRamp(filtered[i].w / max(viewer.heatMax, 1.0));
    }
    return vec3(1.0, 0.0, 1.0);
}

// The tone-mapped image in display-linear light.
vec3 imageColor(uint i) { return toneMapped(viewer.denoise != 0u ? filtered[i].rgb : history[i].color); }

// The debug view over the image at pixel p: over all of it, or scaled down into the small
// window at the bottom right (nearest pixel), framed by a one-pixel white line.
vec3 withDebugView(ivec2 p, vec3 image) {
    if (viewer.debugInset == 0u) return mix(image, debugColor(pixelIndex(p)), viewer.debugOpacity);
    ivec2 size = ivec2(frame.width, frame.height);
    ivec2 inset = max(size / int(PN_DEBUG_INSET_DIVISOR), ivec2(1));
    ivec2 q = p - (size - int(PN_DEBUG_INSET_MARGIN) - inset);  // p in the window's pixels
    if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, inset))) {
        ivec2 source = min(ivec2((vec2(q) + 0.5) * vec2(size) / vec2(inset)), size - 1);
        return mix(image, debugColor(pixelIndex(source)), viewer.debugOpacity);
    }
    bool frameLine = all(greaterThanEqual(q, ivec2(-1))) && all(lessThanEqual(q, inset));
    return frameLine ? vec3(1.0) : image;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    vec3 rgb = imageColor(i);
    if (viewer.debugMode != PN_DEBUG_NONE) rgb = withDebugView(p, rgb);
    display[i] = displayPixel(rgb);
}
