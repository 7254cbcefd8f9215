#version 460
// Display: exposure, a tone curve and sRGB encoding of the temporal (or denoised) radiance, or a
// debug view, packed as RGBA8 for the copy to the window. Must match src/image/tonemap.cpp.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"

layout(std430, set = 0, binding = PN_BINDING_HISTORY_OUT) readonly buffer HistoryBuffer { HistoryTexel history[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) readonly buffer FilteredBuffer { vec4 filtered[]; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_DISPLAY) writeonly buffer DisplayBuffer { uint display[]; };

float reinhard(float x) { return x > 0.0 ? (isinf(x) ? 1.0 : x / (1.0 + x)) : 0.0; }

// Narkowicz's fit of the ACES reference rendering and output transforms.
float acesFilmic(float x) {
    if (!(x > 0.0)) return 0.0;
    if (isinf(x)) return 1.0;
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

float srgbOetf(float x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055; }

uint toSrgb8(float linear) {
    float v = linear > 0.0 ? min(linear, 1.0) : 0.0;
    return uint(srgbOetf(v) * 255.0 + 0.5);
}

// Blue (0) through green and yellow to red (1): the heat-map legend uses the same ramp.
vec3 heatRamp(float t) {
    t = clamp(t, 0.0, 1.0);
    return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

// Debug views are display colours already (no tone curve), in linear light.
vec3 debugColor(uint i) {
    GBufferTexel g = gbuffer[i];
    switch (viewer.debugMode) {
        case PN_DEBUG_NORMALS: return g.surfaceId == 0u ? vec3(0.0) : g.normal * 0.5 + 0.5;
        case PN_DEBUG_ALBEDO: return g.albedo;
        case PN_DEBUG_DEPTH: return vec3(g.depth > 0.0 ? 1.0 / (1.0 + g.depth) : 0.0);
        case PN_DEBUG_MOTION: return vec3(min(abs(g.motion) * 0.1, vec2(1.0)), 0.0);
        case PN_DEBUG_SAMPLES: return heatRamp(history[i].samples / max(viewer.heatMax, 1.0));
        case PN_DEBUG_HEAT_NODES: return heatRamp(filtered[i].x / max(viewer.heatMax, 1.0));
        case PN_DEBUG_HEAT_TRIS: return heatRamp(filtered[i].y / max(viewer.heatMax, 1.0));
    }
    return vec3(1.0, 0.0, 1.0);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    vec3 rgb;
    if (viewer.debugMode != PN_DEBUG_NONE) {
        rgb = debugColor(i);
    } else {
        vec3 radiance = (viewer.denoise != 0u ? filtered[i].rgb : history[i].color) * exp2(viewer.exposure);
        rgb = viewer.toneMapper == PN_TONEMAP_ACES
                  ? vec3(acesFilmic(radiance.r), acesFilmic(radiance.g), acesFilmic(radiance.b))
                  : vec3(reinhard(radiance.r), reinhard(radiance.g), reinhard(radiance.b));
    }
    display[i] = toSrgb8(rgb.r) | (toSrgb8(rgb.g) << 8) | (toSrgb8(rgb.b) << 16) | (255u << 24);
}
