#version 460
// One a-trous wavelet pass of an SVGF-style denoiser: a 5x5 B3-spline kernel whose taps are
// push.passIndex pixels apart (1, 2, 4, ...), weighted down across normal and depth edges and
// across luminance differences large compared with the local noise (the variance channel, which
// each pass filters with the squared weights). It runs on illumination (albedo divided out by
// temporal.comp); the last pass multiplies the albedo back, so texture detail is never blurred,
// weighs the result against the pixel's own running mean (blendWithMean: as the mean converges
// the output tends to it, so a still view converges to the image `penumbra render` makes), and
// may write the display too (PN_ATROUS_DISPLAY). Pixels whose guide depth is not positive (the
// sky, emitters, sprites: PN_GBUFFER_UNFILTERED) are neither filtered nor taps.
#extension GL_GOOGLE_include_directive : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/viewer_common.glsl"
#include "lib/display.glsl"

layout(push_constant) uniform PushBlock { PassPush push; };
layout(std430, set = 0, binding = PN_BINDING_GBUFFER) readonly buffer GBufferIn { GBufferTexel gbuffer[]; };
layout(std430, set = 0, binding = PN_BINDING_DENOISE_GUIDE) readonly buffer GuideIn { vec4 guide[]; };
// This frame's history, as temporal.comp wrote it: the running mean and its variance.
layout(std430, set = 0, binding = PN_BINDING_HISTORY_OUT) readonly buffer HistoryNow { HistoryTexel history[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_IN) readonly buffer FilterIn { vec4 src[]; };
layout(std430, set = 0, binding = PN_BINDING_FILTER_OUT) writeonly buffer FilterOut { vec4 dst[]; };
layout(std430, set = 0, binding = PN_BINDING_DISPLAY) writeonly buffer DisplayBuffer { uint display[]; };

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const float kLog2e = 1.4426950409;  // exp(x) = exp2(x * log2(e))
// The 3x3 Gaussian that smooths the variance estimate: the linear B-spline (1/4, 1/2, 1/4).
const float kB1[2] = float[2](1.0 / 2.0, 1.0 / 4.0);
// Frames of history below which the output is the filter's alone (blendWithMean).
const float kShortHistoryFrames = 4.0;

// A neighbour's depth for the slope (an unfiltered pixel's guide holds it negated).
float depthAt(ivec2 q, float fallback) { return insideImage(q) ? abs(guide[pixelIndex(q)].w) : fallback; }

// What every tap is compared with: the centre pixel's guide and noise level.
struct Centre {
    vec3 normal;
    float depth;
    vec2 depthSlope;   // sigmaDepth times the depth gradient per tap step, so slanted surfaces are not cut into strips
    float luminance;
    float invLumScale; // log2(e) over the luminance tolerance
};

struct FilterSums {
    vec3 color;
    float variance;
    float weight;
};

// Adds the tap `tap` steps from p (push.passIndex pixels per step) with kernel weight `kernel`. The
// three edge-stopping weights, pow(max(cos, 0), sigmaNormal) * exp(-depthTerm) * exp(-lumTerm), are
// folded into one exp2. A cosine <= 0 gives log2 of a tiny floor, so the weight rounds to 0 as
// pow(0, sigma) does, with no 0 * -inf. `nearEdge` (a literal at each call, so it compiles away)
// is for pixels whose footprint may leave the image: a tap outside reads the nearest pixel and
// weighs 0, so the loops unroll into straight-line code either way.
void addTap(inout FilterSums sums, Centre c, ivec2 p, ivec2 tap, float kernel, bool nearEdge) {
    ivec2 q = p + tap * int(push.passIndex);
    uint qi = pixelIndex(nearEdge ? clampToImage(q) : q);
    vec4 tapGuide = guide[qi];
    float tapDepth = tapGuide.w;
    bool usable = (!nearEdge || insideImage(q)) && tapDepth > 0.0;
    vec4 s = src[qi];
    float cosNormal = max(dot(c.normal, tapGuide.xyz), 1e-30);
    float depthScale = abs(dot(c.depthSlope, vec2(tap))) + 1e-3 * c.depth;
    float exponent = viewer.sigmaNormal * log2(cosNormal) - kLog2e * abs(c.depth - tapDepth) / depthScale -
                     abs(c.luminance - luminance(s.rgb)) * c.invLumScale;
    float w = usable ? kernel * exp2(exponent) : 0.0;
    sums.color += w * s.rgb;
    sums.variance += w * w * s.a;
    sums.weight += w;
}

// The 5x5 taps around p; the centre's own weight is its kernel weight (it matches itself), so it
// is added up front rather than computed.
FilterSums filterTaps(Centre c, ivec2 p, vec4 centre, bool nearEdge) {
    float k0 = kB3[0] * kB3[0];
    FilterSums sums = FilterSums(k0 * centre.rgb, k0 * k0 * centre.a, k0);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
            if (dx != 0 || dy != 0) addTap(sums, c, p, ivec2(dx, dy), kB3[abs(dx)] * kB3[abs(dy)], nearEdge);
    return sums;
}

// The filtered radiance F against the pixel's running mean R of N samples, weighted for the least
// squared error: R is unbiased with the variance of its mean vR (temporal.comp); F has variance vF
// (this filter's estimate) and a bias the filter cannot see, estimated as what of (F - R)^2 the
// noise of R does not explain: b^2 = max((F - R)^2 - vR, 0). F's weight is vR / (vR + vF + b^2),
// but at least 4 frames' worth of samples over N (A-SVGF and Quake II RTX let the history length
// set the filter's reach in the same way): while the history is short, one pixel's vR is too
// noisy to judge by (a firefly passes for bias, and would be kept), and the filter is what helps.
// At rest vR and 4 / N both fall, so the output converges to the mean, whatever the filter's bias.
vec3 blendWithMean(vec3 filtered, float filteredVariance, HistoryTexel h) {
    vec3 d = filtered - h.color;
    float meanVariance = min(h.meanVariance, 1e30);
    float bias2 = max(dot(d, d) * (1.0 / 3.0) - meanVariance, 0.0);
    float weight = meanVariance / (meanVariance + filteredVariance + bias2 + 1e-30);
    float shortHistory = kShortHistoryFrames * float(viewer.samplesPerFrame) / max(h.samples, 1.0);
    return h.color + clamp(max(weight, shortHistory), 0.0, 1.0) * d;
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
        int step = int(push.passIndex);
        vec2 gradient = 0.5 * vec2(depthAt(p + ivec2(1, 0), depth) - depthAt(p - ivec2(1, 0), depth),
                                   depthAt(p + ivec2(0, 1), depth) - depthAt(p - ivec2(0, 1), depth));
        c.depthSlope = viewer.sigmaDepth * float(step) * gradient;
        c.luminance = luminance(centre.rgb);
        c.invLumScale = kLog2e / (viewer.sigmaLuminance * sqrt(max(variance / kernelSum, 0.0)) + 1e-6);
        bool nearEdge = any(lessThan(p, ivec2(2 * step))) || any(greaterThanEqual(p + 2 * step, ivec2(frame.width, frame.height)));
        FilterSums sums = nearEdge ? filterTaps(c, p, centre, true) : filterTaps(c, p, centre, false);
        // The centre tap always has a weight > 0.
        result = vec4(sums.color / sums.weight, sums.variance / (sums.weight * sums.weight));
    }
    if ((push.mode & PN_ATROUS_LAST) != 0u) {
        HistoryTexel h = history[i];
        if (depth > 0.0) {
            vec3 albedo = demodulationAlbedo(gbuffer[i]);
            float albedoLuminance = max(luminance(albedo), 1e-3);
            result.rgb *= albedo;
            if ((push.mode & PN_ATROUS_FILTER_ONLY) == 0u)
                result.rgb = blendWithMean(result.rgb, result.a * albedoLuminance * albedoLuminance, h);
        } else {
            result.rgb = h.color;  // exactly the mean, not the mean divided and multiplied by 1
        }
    }
    dst[i] = result;
    // What the tonemap pass would make of it, saving that pass a read of the image and a barrier.
    if ((push.mode & PN_ATROUS_DISPLAY) != 0u) display[i] = displayPixel(toneMapped(result.rgb));
}
