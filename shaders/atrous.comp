#version 460
// One a-trous wavelet pass of an SVGF-style denoiser: a 5x5 B3-spline kernel whose taps are
// push.passIndex pixels apart (1, 2, 4, ...), weighted down across normal and depth edges and
// across luminance differences large compared with the local noise (the variance channel, which
// each pass filters with the squared weights). It runs on illumination (albedo divided out by
// temporal.comp); the last pass multiplies the albedo back, so texture detail is never blurred.
//
// A group filters a lattice of pixels `step` apart (shared/atrous_tiles.h), so every tap of every
// thread lands on the 12x12 lattice the group reads once into shared memory: each texel is read
// from memory about twice per pass instead of 25 times, and its normal decoded once, not per tap.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"
#include "shared/atrous_tiles.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"

layout(push_constant) uniform PushBlock { PassPush push; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_DENOISE_GUIDE) readonly buffer GuideIn { DenoiseGuide guide[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_IN) readonly buffer FilterIn { vec4 src[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer FilterOut { vec4 dst[]; };

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const uint kApron = PN_ATROUS_APRON;

// The group's lattice: illumination and variance; shading normal and depth (0: the primary ray
// missed, -1: outside the image); luminance.
shared vec4 latticeColor[kApron * kApron];
shared vec4 latticeGuide[kApron * kApron];
shared float latticeLuminance[kApron * kApron];

ivec2 latticePixel(ivec2 point, uint step) {
    return ivec2(atrousLatticePixel(gl_WorkGroupID.x, point.x, step), atrousLatticePixel(gl_WorkGroupID.y, point.y, step));
}

void loadLattice(uint step) {
    uint threads = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    for (uint k = gl_LocalInvocationIndex; k < kApron * kApron; k += threads) {
        ivec2 q = latticePixel(ivec2(k % kApron, k / kApron) - 2, step);
        vec4 color = vec4(0.0), g = vec4(0.0, 0.0, 1.0, -1.0);
        if (insideImage(q)) {
            uint qi = pixelIndex(q);
            color = src[qi];
            DenoiseGuide tap = guide[qi];
            g = vec4(octDecode(unpackSnorm2x16(tap.normal)), tap.depth);
        }
        latticeColor[k] = color;
        latticeGuide[k] = g;
        latticeLuminance[k] = luminance(color.rgb);
    }
}

uint latticeIndex(ivec2 point) { return uint(point.y + 2) * kApron + uint(point.x + 2); }

// Local noise: 3x3 Gaussian of the variance over the lattice (a single pixel's estimate is itself
// noisy); at step 1 these are the pixel's neighbours, at larger steps the filter's own scale.
float localVariance(ivec2 point) {
    float variance = 0.0, kernelSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            uint k = latticeIndex(point + ivec2(dx, dy));
            if (latticeGuide[k].w < 0.0) continue;
            float w = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25);
            variance += w * latticeColor[k].a;
            kernelSum += w;
        }
    return variance / kernelSum;
}

vec4 filtered(ivec2 point, vec2 gradient, int step) {
    uint centreIndex = latticeIndex(point);
    vec4 centre = latticeColor[centreIndex];
    vec3 normal = latticeGuide[centreIndex].xyz;
    float depth = latticeGuide[centreIndex].w;
    // The three edge-stopping weights, pow(max(cos, 0), sigmaNormal) * exp(-depthTerm) *
    // exp(-lumTerm), are folded into one exp2 per tap. A cosine <= 0 gives log2 of a tiny floor,
    // so the weight rounds to 0 as pow(0, sigma) does, with no 0 * -inf.
    const float kLog2e = 1.4426950409;
    float invLumScale = kLog2e / (viewer.sigmaLuminance * sqrt(max(localVariance(point), 0.0)) + 1e-6);
    float centreLum = latticeLuminance[centreIndex];
    vec3 colorSum = vec3(0.0);
    float varianceSum = 0.0, weightSum = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            uint k = latticeIndex(point + ivec2(dx, dy));
            vec4 tapGuide = latticeGuide[k];
            if (!(tapGuide.w > 0.0)) continue;  // a miss, or outside the image
            vec4 s = latticeColor[k];
            float cosNormal = max(dot(normal, tapGuide.xyz), 1e-30);
            float depthScale = viewer.sigmaDepth * abs(dot(gradient, vec2(dx, dy) * float(step))) + 1e-3 * depth;
            float exponent = viewer.sigmaNormal * log2(cosNormal) - kLog2e * abs(depth - tapGuide.w) / depthScale -
                             abs(centreLum - latticeLuminance[k]) * invLumScale;
            float w = kB3[abs(dx)] * kB3[abs(dy)] * exp2(exponent);
            colorSum += w * s.rgb;
            varianceSum += w * w * s.a;
            weightSum += w;
        }
    // The centre tap always has weight kB3[0]^2 > 0.
    return vec4(colorSum / weightSum, varianceSum / (weightSum * weightSum));
}

void main() {
    uint step = push.passIndex;
    loadLattice(step);
    barrier();
    ivec2 point = ivec2(gl_LocalInvocationID.xy);
    ivec2 p = latticePixel(point, step);
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    vec4 result = latticeColor[latticeIndex(point)];
    if (latticeGuide[latticeIndex(point)].w > 0.0) result = filtered(point, guide[i].depthGradient, int(step));
    if ((push.mode & PN_ATROUS_LAST) != 0u) result.rgb *= demodulationAlbedo(gbuffer[i]);
    dst[i] = result;
}
