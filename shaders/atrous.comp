#version 460
// One a-trous wavelet pass of an SVGF-style denoiser: a 5x5 B3-spline kernel whose taps are
// push.passIndex pixels apart (1, 2, 4, ...), weighted down across normal and depth edges and
// across luminance differences large compared with the local noise (the variance channel, which
// each pass filters with the squared weights). It runs on illumination (albedo divided out by
// temporal.comp); the last pass multiplies the albedo back, so texture detail is never blurred.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"

layout(push_constant) uniform PushBlock { PassPush push; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_DENOISE_GUIDE) readonly buffer GuideIn { uvec2 guide[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_IN) readonly buffer FilterIn { vec4 src[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer FilterOut { vec4 dst[]; };

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

float depthAt(ivec2 q, float fallback) { return insideImage(q) ? uintBitsToFloat(guide[pixelIndex(q)].y) : fallback; }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    uvec2 centreGuide = guide[i];
    float depth = uintBitsToFloat(centreGuide.y);
    vec3 normal = octDecode(unpackSnorm2x16(centreGuide.x));
    vec4 centre = src[i];
    vec4 result = centre;
    if (depth > 0.0) {
        // Local noise: 3x3 Gaussian of the variance (a single pixel's estimate is itself noisy).
        float variance = 0.0, kernelSum = 0.0;
        // Branch-free (taps outside the image read the nearest pixel and weigh 0), so the
        // loops unroll into straight-line code.
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                ivec2 q = p + ivec2(dx, dy);
                float k = insideImage(q) ? (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25) : 0.0;
                variance += k * src[pixelIndex(clampToImage(q))].a;
                kernelSum += k;
            }
        // The three edge-stopping weights, pow(max(cos, 0), sigmaNormal) * exp(-depthTerm) *
        // exp(-lumTerm), are folded into one exp2 per tap: the filter is bound by special-function
        // throughput (log, exp, reciprocal), not by its reads. A cosine <= 0 gives log2 of a tiny
        // floor, so the weight rounds to 0 as pow(0, sigma) does, with no 0 * -inf.
        const float kLog2e = 1.4426950409;
        float invLumScale = kLog2e / (viewer.sigmaLuminance * sqrt(max(variance / kernelSum, 0.0)) + 1e-6);
        // Screen-space depth gradient, so slanted surfaces are not cut into strips.
        vec2 gradient = 0.5 * vec2(depthAt(p + ivec2(1, 0), depth) - depthAt(p - ivec2(1, 0), depth),
                                   depthAt(p + ivec2(0, 1), depth) - depthAt(p - ivec2(0, 1), depth));
        int step = int(push.passIndex);
        float centreLum = luminance(centre.rgb);
        vec3 colorSum = vec3(0.0);
        float varianceSum = 0.0, weightSum = 0.0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                ivec2 offset = ivec2(dx, dy) * step;
                ivec2 q = p + offset;
                uint qi = pixelIndex(clampToImage(q));
                uvec2 tapGuide = guide[qi];
                float tapDepth = uintBitsToFloat(tapGuide.y);
                bool usable = insideImage(q) && tapDepth > 0.0;
                vec4 s = src[qi];
                float cosNormal = max(dot(normal, octDecode(unpackSnorm2x16(tapGuide.x))), 1e-30);
                float depthScale = viewer.sigmaDepth * abs(dot(gradient, vec2(offset))) + 1e-3 * depth;
                float exponent = viewer.sigmaNormal * log2(cosNormal) - kLog2e * abs(depth - tapDepth) / depthScale -
                                 abs(centreLum - luminance(s.rgb)) * invLumScale;
                float w = usable ? kB3[abs(dx)] * kB3[abs(dy)] * exp2(exponent) : 0.0;
                colorSum += w * s.rgb;
                varianceSum += w * w * s.a;
                weightSum += w;
            }
        // The centre tap always has weight kB3[0]^2 > 0.
        result = vec4(colorSum / weightSum, varianceSum / (weightSum * weightSum));
    }
    if ((push.mode & PN_ATROUS_LAST) != 0u) result.rgb *= demodulationAlbedo(gbuffer[i]);
    dst[i] = result;
}
