// One path's life between its rays, shared by the megakernel (trace.comp) and the wavefront
// kernels (wave_*.comp): the path state, what a vertex does with its closest hit (emission, one
// light sample, one BSDF sample, roulette) and the light its shadow ray carries. Include after
// shared/types.h, lib/scene_bindings.glsl and lib/trace_outputs.glsl (the pixel estimates).
#ifndef PN_PATH_GLSL
#define PN_PATH_GLSL

#include "lib/rng.glsl"
#include "lib/sampling.glsl"
#include "lib/offset.glsl"
#include "lib/bvh.glsl"
#include "lib/camera.glsl"
#include "shared/pass_jitter.h"
#include "lib/surface.glsl"
#include "lib/light_sampler.glsl"
#include "lib/material.glsl"
#include "lib/shading_frame.glsl"
#include "lib/mis.glsl"

// Everything light samplers need about the shading point.
struct ShadingPoint {
    Surface surface;
    ShadingFrame frame;
    BsdfParams bsdf;
    vec3 wo;            // local frame, toward the previous vertex
    vec3 mediumAbove;   // absorption coefficient on wo's side (the medium the path is in)
    vec3 mediumBelow;   // absorption coefficient beyond the surface (where refraction goes)
};

// The ray origin for leaving s toward wi (world): off the side of the surface wi goes to.
vec3 leavingOrigin(Surface s, vec3 wi) {
    return offsetRayOrigin(s.position, dot(wi, s.geometricNormal) > 0.0 ? s.geometricNormal : -s.geometricNormal);
}

// The light a light sample brings, arriving at the shading point along ls.wi (world) from
// ls.dist away, if nothing blocks it: radiance / pdf weighted by the BSDF, absorption and MIS. The
// pdf is a solid-angle density, or for a delta light the probability of having picked it (isDelta).
vec3 unoccludedLight(ShadingPoint sp, LightSample ls) {
    vec3 wi = ls.wi, radiance = ls.radiance;
    float dist = ls.dist, lightPdf = ls.pdf;
    bool isDeltaLight = ls.isDelta;
    if (!(lightPdf > 0.0) || max(radiance.r, max(radiance.g, radiance.b)) <= 0.0) return vec3(0.0);
    vec3 wiLocal = toLocal(sp.frame, wi);
    // The shading and the true surface must agree on which side wi is, or light would leak.
    bool above = dot(wi, sp.surface.geometricNormal) > 0.0;
    if (above != (wiLocal.z > 0.0) || wiLocal.z == 0.0) return vec3(0.0);
    vec3 f = bsdfEval(sp.bsdf, sp.wo, wiLocal);
    if (max(f.r, max(f.g, f.b)) <= 0.0) return vec3(0.0);
    float weight = isDeltaLight ? 1.0 : misWeightLight(lightPdf, bsdfPdf(sp.bsdf, sp.wo, wiLocal));
    if (weight <= 0.0) return vec3(0.0);
    vec3 sigma = above ? sp.mediumAbove : sp.mediumBelow;
    vec3 transmittance = dist == PN_INFINITY ? vec3(sigma == vec3(0.0) ? 1.0 : 0.0) : exp(-sigma * dist);
    return f * abs(wiLocal.z) * radiance * transmittance * (weight / lightPdf);
}

// One path of one pixel sample, between two of its rays.
struct Path {
    vec3 origin;     // the next ray
    vec3 direction;
    vec3 throughput;
    vec3 result;     // radiance gathered so far
    vec3 medium;     // absorption coefficient of the medium the ray travels in
    vec3 previousNormal;    // shading normal where the current direction was sampled
    vec3 previousPosition;  // and the surface point there (what light sampling saw)
    float bsdfPdfPrev;      // solid-angle pdf of the direction that led here
    bool afterDelta;        // the camera ray, or a delta lobe: light sampling could not see this
    uint depth;
    uint sampleIndex;
    uint rng;
};

// The direct light a path's vertex is waiting for: `light` arrives unless `ray` is blocked.
struct PendingShadow {
    ShadowRay ray;
    vec3 light;
    bool pending;
};

PendingShadow noShadow() { return PendingShadow(ShadowRay(vec3(0.0), vec3(0.0, 0.0, 1.0), 0.0), vec3(0.0), false); }

// The path's camera ray is its own, or under PN_TRACE_SHARED_CAMERA (sharedCamera) its pass's: the
// pass's R2 point in the pixel (shared/pass_jitter.h) and a lens point from the pass's first
// sample's stream. The path's stream makes the same draws either way, so its later numbers do not
// depend on whose camera ray it took.
Path startPath(uvec2 pixel, uint pixelIndex, uint sampleIndex, bool sharedCamera) {
    Path path;
    path.rng = rngSeed(pixelIndex, sampleIndex, frame.seed);
    bool jittered = (frame.flags & PN_FRAME_NO_JITTER) == 0u;
    vec2 jitter = rngNext2(path.rng);  // drawn either way, so later draws stay the same
    cameraRay(vec2(pixel) + (jittered ? jitter : vec2(0.5)), path.rng, path.origin, path.direction);
    if (sharedCamera) {
        uint pass = sampleIndex / frame.samplesPerPass;
        uint rotation = pcgHash(pixelIndex ^ pcgHash(frame.seed ^ 0x85ebca6bu));
        uint lensRng = rngSeed(pixelIndex, pass * frame.samplesPerPass, frame.seed);
        vec2 inPixel = jittered ? passJitter(rotation, pcgHash(rotation), pass) : vec2(0.5);
        cameraRay(vec2(pixel) + inPixel, lensRng, path.origin, path.direction);
    }
    path.throughput = vec3(1.0);
    path.result = vec3(0.0);
    path.medium = vec3(0.0);
    path.previousNormal = vec3(0.0);
    path.previousPosition = vec3(0.0);
    path.bsdfPdfPrev = 0.0;
    path.afterDelta = true;
    path.depth = 0u;
    path.sampleIndex = sampleIndex;
    return path;
}

// Shadow-ray roulette (after Vorba & Krivanek 2016, "Adjoint-driven Russian roulette and
// splitting", with the pixel's estimate standing in for the adjoint): a light sample that would
// add less than frame.shadowRouletteShare of what the pixel holds per sample, in every channel, is
// traced with probability (its largest share / that share) and weighted by the inverse. The mean
// is unchanged and the variance it adds is at most threshold^2 / 4 per ray, while most of a
// many-light scene's shadow rays carry little (DOOM1 E1M1, 1280x800 x 4: more than half of them go
// at a share of 0.1). The estimate comes from earlier passes only, never from this path's own
// numbers, so the roulette cannot bias the pass.
bool keepShadowRay(inout vec3 light, uint pixelIndex, inout uint rng) {
    if (!PN_HAS(PN_FEATURE_SHADOW_ROULETTE) || frame.shadowRouletteShare == 0.0) return true;
    // Channel by channel, so that a coloured light is weighed against the pixel's own value in its
    // colour: the channel that brings the largest share decides. A channel without a scale keeps
    // the ray (its ratio is huge), one the light does not reach has no say (0).
    vec3 threshold = frame.shadowRouletteShare * pixelEstimate(pixelIndex);
    vec3 share = light / max(threshold, vec3(1e-30));
    float survive = max(share.r, max(share.g, share.b));
    if (!(survive < 1.0)) return true;
    if (rngNext(rng) >= survive) return false;
    light /= survive;
    return true;
}

// Direct light at a shading point: one light chosen among all of them by the unified sampler
// (with pickU, a stratified number), one sample of it; its shadow ray is left for the caller.
PendingShadow sampleDirectLight(ShadingPoint sp, vec3 throughput, float pickU, uint pixelIndex, inout uint rng) {
    PendingShadow shadow = noShadow();
    LightPick pick = pickLight(sp.surface.position, sp.frame.n, pickU, rng);
    if (pick.ref == PN_NO_LIGHT) return shadow;
    LightSample ls = sampleChosenLight(pick, sp.surface.position, sp.frame.n, rng);
    shadow.light = throughput * unoccludedLight(sp, ls);
    shadow.ray = shadowRayTo(leavingOrigin(sp.surface, ls.wi), ls);
    shadow.pending = shadow.light != vec3(0.0) && keepShadowRay(shadow.light, pixelIndex, rng);
    return shadow;
}

// The path meets `hit` (its closest hit along its ray): gathers emission there, leaves the
// vertex's light sample in `shadow` and samples the BSDF for the next ray. False: the path ends
// (its pending shadow ray, if any, still counts). pixelIndex and the path's sample index stratify
// the light picks of a pixel's samples (one R1 sequence per path depth).
bool extendPath(inout Path path, Hit hit, uint pixelIndex, out PendingShadow shadow) {
    shadow = noShadow();
    if (hit.triangle == PN_NO_HIT) {
        // Escaping inside an absorbing medium (an open mesh) leaves nothing.
        if (path.medium == vec3(0.0))
            path.result += path.throughput * escapedRadiance(path.previousPosition, path.previousNormal, path.direction,
                                                             path.afterDelta ? 0.0 : path.bsdfPdfPrev);
        return false;
    }
    if (PN_HAS(PN_FEATURE_ABSORPTION)) path.throughput *= exp(-path.medium * hit.t);
    Surface s = surfaceAt(hit, path.origin, path.direction);
    Material m = materials[s.material];

    if ((m.flags & PN_MATERIAL_EMISSIVE) != 0u && s.frontFace) {
        float lightPdf = 0.0;
        if (!path.afterDelta && s.lightIndex != PN_NO_LIGHT && misSamplesLights())
            lightPdf = emitterHitPdf(hit, s, path.previousPosition, path.previousNormal, path.origin, path.direction);
        path.result += path.throughput * emittedRadiance(m, s.uv, path.direction, path.depth == 0u) *
                       misWeightHit(path.bsdfPdfPrev, lightPdf, path.afterDelta);
    }
    if (path.depth >= frame.maxBounces) return false;

    ShadingPoint sp;
    sp.surface = s;
    sp.frame = shadingFrameAt(s, m, hit.triangle, -path.direction);
    sp.bsdf = materialBsdf(m, s.uv, s.frontFace);
    sp.wo = toLocal(sp.frame, -path.direction);
    sp.mediumAbove = path.medium;
    // Refraction leaves the medium through a back face and enters the material's through a front one.
    sp.mediumBelow = PN_HAS(PN_FEATURE_ABSORPTION) && s.frontFace ? m.absorption : vec3(0.0);

    float pickU = stratifiedSample(pixelIndex, path.depth, path.sampleIndex, frame.seed);
    shadow = sampleDirectLight(sp, path.throughput, pickU, pixelIndex, path.rng);

    vec3 u = vec3(rngNext2(path.rng), rngNext(path.rng));
    BsdfSample bs = bsdfSample(sp.bsdf, sp.wo, u);
    if (!(bs.pdf > 0.0) || max(bs.weight.r, max(bs.weight.g, bs.weight.b)) <= 0.0) return false;
    vec3 wi = toWorld(sp.frame, bs.wi);
    // A sample on the other side of the true surface than the shading frame says would leak
    // light through it (or carry none): the path ends.
    bool above = dot(wi, s.geometricNormal) > 0.0;
    if (above != (bs.wi.z > 0.0)) return false;
    path.throughput *= bs.weight;
    path.bsdfPdfPrev = bs.pdf;
    path.afterDelta = bs.isDelta;
    if (!above) path.medium = sp.mediumBelow;

    if (path.depth + 1u >= frame.rouletteStart) {
        float survive = min(max(path.throughput.r, max(path.throughput.g, path.throughput.b)), 1.0);
        if (rngNext(path.rng) >= survive) return false;
        path.throughput /= survive;
    }
    path.origin = leavingOrigin(s, wi);
    path.direction = wi;
    path.previousNormal = sp.frame.n;
    path.previousPosition = s.position;
    ++path.depth;
    return true;
}

// Follows the path from its current ray to its end, tracing each vertex's shadow ray as soon as
// the vertex has sampled its light and BSDF (so the shading point's state is dead during that
// traversal); counts the rays traced.
void finishPath(inout Path path, uint pixelIndex, inout uint closestRays, inout uint shadowRays) {
    bool alive = true;
    while (alive) {
        ++closestRays;
        Hit hit = traceClosest(path.origin, path.direction, PN_INFINITY);
        PendingShadow shadow;
        alive = extendPath(path, hit, pixelIndex, shadow);
        if (shadow.pending) {
            ++shadowRays;
            if (!traceOccluded(shadow.ray.origin, shadow.ray.direction, shadow.ray.tMax)) path.result += shadow.light;
        }
    }
}

#endif
