#version 460
// One a-trous wavelet pass of an SVGF-style denoiser: a 5x5 B3-spline kernel whose taps are
// push.passIndex pixels apart (1, 2, 4, ...), weighted down across normal and depth edges and
// across luminance differences large compared with the local noise (the variance channel, which
// each pass filters with the squared weights). It runs on illumination (albedo divided out by
// temporal.comp); the last pass multiplies the albedo back, so texture detail is never blurred.
// Input and output are denoiser texels (guide and half-float signal in one uvec4, shared/types.h);
// the last pass writes float vec4(radiance, variance) instead, for tonemap.comp.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"

layout(push_constant) uniform PushBlock { PassPush push; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_IN) readonly buffer FilterIn { uvec4 src[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer FilterOut { uvec4 dst[]; };

// PN_ATROUS_TILE_TEXELS in the pipeline for steps up to PN_ATROUS_TILE_MAX_STEP, whose workgroup
// first loads its footprint into `tile` (each texel is read by up to 25 + 9 + 4 of its pixels'
// taps); 1 in the pipeline for larger steps, which reads the buffer directly.
layout(constant_id = 0) const uint kTileTexels = 1;
shared uvec4 tile[kTileTexels];

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);

// The image pixel held in tile[0].
ivec2 tileOrigin() { return ivec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy) - PN_ATROUS_TILE_RADIUS; }

// Only the texels within 2 x step of the workgroup are loaded (a step-1 pass leaves the outer
// rows and columns of the tile unread).
void loadTile(int step) {
    ivec2 origin = tileOrigin();
    ivec2 lo = ivec2(PN_ATROUS_TILE_RADIUS - 2 * step);
    ivec2 hi = ivec2(PN_ATROUS_TILE_WIDTH, PN_ATROUS_TILE_HEIGHT) - lo;
    for (uint k = gl_LocalInvocationIndex; k < PN_ATROUS_TILE_TEXELS; k += PN_TRACE_GROUP_X * PN_TRACE_GROUP_Y) {
        ivec2 t = ivec2(k % PN_ATROUS_TILE_WIDTH, k / PN_ATROUS_TILE_WIDTH);
        ivec2 q = origin + t;
        if (all(greaterThanEqual(t, lo)) && all(lessThan(t, hi)))
            tile[k] = insideImage(q) ? src[pixelIndex(q)] : uvec4(0u);
    }
    barrier();
}

// The texel at image pixel q (inside the image; within the tile's radius of this workgroup in a
// tiled pipeline), and one word of it.
uint tileIndex(ivec2 q) {
    ivec2 t = q - tileOrigin();
    return uint(t.y * PN_ATROUS_TILE_WIDTH + t.x);
}
uvec4 texelAt(ivec2 q) { return kTileTexels > 1u ? tile[tileIndex(q)] : src[pixelIndex(q)]; }
uint texelWord(ivec2 q, int word) { return kTileTexels > 1u ? tile[tileIndex(q)][word] : src[pixelIndex(q)][word]; }

float depthAt(ivec2 q, float fallback) { return insideImage(q) ? denoiseDepth(texelWord(q, 1)) : fallback; }

// The filtered (illumination, variance) at p, whose texel is `centre`.
vec4 filterAt(ivec2 p, uvec4 centre) {
    float depth = denoiseDepth(centre.y);
    vec4 signal = denoiseSignal(centre);
    if (!(depth > 0.0)) return signal;
    vec3 normal = denoiseNormal(centre.x);
    // Local noise: 3x3 Gaussian of the variance (a single pixel's estimate is itself noisy).
    float variance = 0.0, kernelSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (!insideImage(q)) continue;
            float k = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25);
            variance += k * denoiseVariance(texelWord(q, 3));
            kernelSum += k;
        }
    // The three edge-stopping weights, pow(max(cos, 0), sigmaNormal) * exp(-depthTerm) *
    // exp(-lumTerm), are folded into one exp2 per tap. A cosine <= 0 gives log2 of a tiny floor,
    // so the weight rounds to 0 as pow(0, sigma) does, with no 0 * -inf.
    const float kLog2e = 1.4426950409;
    float invLumScale = kLog2e / (viewer.sigmaLuminance * sqrt(max(variance / kernelSum, 0.0)) + 1e-6);
    // Screen-space depth gradient, so slanted surfaces are not cut into strips.
    vec2 gradient = 0.5 * vec2(depthAt(p + ivec2(1, 0), depth) - depthAt(p - ivec2(1, 0), depth),
                               depthAt(p + ivec2(0, 1), depth) - depthAt(p - ivec2(0, 1), depth));
    int step = int(push.passIndex);
    float centreLum = luminance(signal.rgb);
    vec3 colorSum = vec3(0.0);
    float varianceSum = 0.0, weightSum = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 offset = ivec2(dx, dy) * step;
            ivec2 q = p + offset;
            if (!insideImage(q)) continue;
            uvec4 tap = texelAt(q);
            float tapDepth = denoiseDepth(tap.y);
            if (!(tapDepth > 0.0)) continue;
            vec4 s = denoiseSignal(tap);
            float cosNormal = max(dot(normal, denoiseNormal(tap.x)), 1e-30);
            float depthScale = viewer.sigmaDepth * abs(dot(gradient, vec2(offset))) + 1e-3 * depth;
            float exponent = viewer.sigmaNormal * log2(cosNormal) - kLog2e * abs(depth - tapDepth) / depthScale -
                             abs(centreLum - luminance(s.rgb)) * invLumScale;
            float w = kB3[abs(dx)] * kB3[abs(dy)] * exp2(exponent);
            colorSum += w * s.rgb;
            varianceSum += w * w * s.a;
            weightSum += w;
        }
    // The centre tap always has weight kB3[0]^2 > 0.
    return vec4(colorSum / weightSum, varianceSum / (weightSum * weightSum));
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (kTileTexels > 1u) loadTile(int(push.passIndex));  // before any invocation leaves: all reach its barrier
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    uvec4 centre = texelAt(p);
    vec4 result = filterAt(p, centre);
    if ((push.mode & PN_ATROUS_LAST) != 0u) {
        result.rgb *= demodulationAlbedo(gbuffer[i]);
        dst[i] = floatBitsToUint(result);
    } else {
        dst[i] = packDenoiseSignal(centre.xy, result);
    }
}
