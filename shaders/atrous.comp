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
layout(std430, set = 0, binding = PN_BINDING_DENOISE_GUIDE) readonly buffer GuideIn { vec4 guide[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_IN) readonly buffer FilterIn { vec4 src[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer FilterOut { vec4 dst[]; };

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const float kLog2e = 1.4426950409;  // exp(x) = exp2(x * log2(e))
// The 3x3 Gaussian that smooths the variance estimate: the linear B-spline (1/4, 1/2, 1/4).
const float kB1[2] = float[2](1.0 / 2.0, 1.0 / 4.0);

float depthAt(ivec2 q, float fallback) { return insideImage(q) ? guide[pixelIndex(q)].w : fallback; }

// What every tap is compared with: the centre pixel's guide and noise level.
struct Centre {
    vec3 normal;
    float depth;
    vec2 gradient;     // screen-space depth gradient, so slanted surfaces are not cut into strips
    float luminance;
    float invLumScale; // log2(e) over the luminance tolerance
};

struct FilterSums {
    vec3 color;
    float variance;
    float weight;
};

// Adds the tap at p + offset with kernel weight `kernel`. The three edge-stopping weights,
// pow(max(cos, 0), sigmaNormal) * exp(-depthTerm) * exp(-lumTerm), are folded into one exp2: the
// filter is bound by special-function throughput (log, exp, reciprocal), not by its reads. A
// cosine <= 0 gives log2 of a tiny floor, so the weight rounds to 0 as pow(0, sigma) does, with
// no 0 * -inf. Branch-free: a tap outside the image reads the nearest pixel and weighs 0, so the
// loops unroll into straight-line code.
void addTap(inout FilterSums sums, Centre c, ivec2 p, ivec2 offset, float kernel) {
    ivec2 q = p + offset;
    uint qi = pixelIndex(clampToImage(q));
    vec4 tapGuide = guide[qi];
    float tapDepth = tapGuide.w;
    bool usable = insideImage(q) && tapDepth > 0.0;
    vec4 s = src[qi];
    float cosNormal = max(dot(c.normal, tapGuide.xyz), 1e-30);
    float depthScale = viewer.sigmaDepth * abs(dot(c.gradient, vec2(offset))) + 1e-3 * c.depth;
    float exponent = viewer.sigmaNormal * log2(cosNormal) - kLog2e * abs(c.depth - tapDepth) / depthScale -
                     abs(c.luminance - luminance(s.rgb)) * c.invLumScale;
    float w = usable ? kernel * exp2(exponent) : 0.0;
    sums.color += w * s.rgb;
    sums.variance += w * w * s.a;
    sums.weight += w;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!insideImage(p)) return;
    uint i = pixelIndex(p);
    vec4 centreGuide = guide[i];
    float depth = centreGuide.w;
    vec3 normal = centreGuide.xyz;
    vec4 centre = src[i];
    vec4 result = centre;
    if (depth > 0.0) {
        // Local noise: 3x3 Gaussian of the variance (a single pixel's estimate is itself noisy).
        float variance = 0.0, kernelSum = 0.0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                ivec2 q = p + ivec2(dx, dy);
                float k = insideImage(q) ? kB1[abs(dx)] * kB1[abs(dy)] : 0.0;
                variance += k * src[pixelIndex(clampToImage(q))].a;
                kernelSum += k;
            }
        Centre c;
        c.normal = normal;
        c.depth = depth;
        c.gradient = 0.5 * vec2(depthAt(p + ivec2(1, 0), depth) - depthAt(p - ivec2(1, 0), depth),
                                depthAt(p + ivec2(0, 1), depth) - depthAt(p - ivec2(0, 1), depth));
        c.luminance = luminance(centre.rgb);
        c.invLumScale = kLog2e / (viewer.sigmaLuminance * sqrt(max(variance / kernelSum, 0.0)) + 1e-6);
        int step = int(push.passIndex);
        FilterSums sums = FilterSums(vec3(0.0), 0.0, 0.0);
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) addTap(sums, c, p, ivec2(dx, dy) * step, kB3[abs(dx)] * kB3[abs(dy)]);
        // The centre tap always has a weight > 0.
        result = vec4(sums.color / sums.weight, sums.variance / (sums.weight * sums.weight));
    }
    if ((push.mode & PN_ATROUS_LAST) != 0u) result.rgb *= demodulationAlbedo(gbuffer[i]);
    dst[i] = result;
}
