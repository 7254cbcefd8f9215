#version 460
// The path tracer: one thread per pixel, samplesPerPass paths each, added into the accumulation
// buffer (rgb = sum of radiance, a = sum of squared luminance, for variance estimates).
// Unidirectional path tracing with next event estimation (one light per vertex, chosen among
// emissive triangles and spheres, punctual lights, sun disks and the environment by
// lib/light_sampler.glsl), combined with BSDF sampling per frame.misMode (lib/mis.glsl); every
// surface is shaded by the one principled BSDF (lib/bsdf/bsdf.glsl) in its local shading frame.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require

#include "shared/types.h"

layout(local_size_x = PN_TRACE_GROUP_X, local_size_y = PN_TRACE_GROUP_Y) in;

#include "lib/scene_bindings.glsl"
#include "lib/rng.glsl"
#include "lib/sampling.glsl"
#include "lib/offset.glsl"
#include "lib/bvh.glsl"
#include "lib/camera.glsl"
#include "lib/surface.glsl"
#include "lib/light_sampler.glsl"
#include "lib/material.glsl"
#include "lib/shading_frame.glsl"
#include "lib/mis.glsl"

layout(std430, set = 0, binding = PN_BINDING_ACCUM) buffer AccumBuffer { vec4 accum[]; };
layout(std430, set = 0, binding = PN_BINDING_COUNTERS) buffer CounterBuffer { RayCounters counters; };
layout(std430, set = 0, binding = PN_BINDING_ACTIVE_MASK) readonly buffer ActiveMask { uint activeMask[]; };

uint closestRays = 0u;
uint shadowRays = 0u;

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
// ls.dist away: radiance / pdf weighted by the BSDF, visibility, absorption and MIS. The pdf is a
// solid-angle density, or for a delta light the probability of having picked it (isDelta).
vec3 shadeLightSample(ShadingPoint sp, LightSample ls) {
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
    ++shadowRays;
    if (shadowRayBlocked(leavingOrigin(sp.surface, wi), ls)) return vec3(0.0);
    vec3 sigma = above ? sp.mediumAbove : sp.mediumBelow;
    vec3 transmittance = dist == PN_INFINITY ? vec3(sigma == vec3(0.0) ? 1.0 : 0.0) : exp(-sigma * dist);
    return f * abs(wiLocal.z) * radiance * transmittance * (weight / lightPdf);
}

// Direct light: one light chosen among all of them by the unified sampler (with pickU, a
// stratified number), one sample of it, one shadow ray.
vec3 sampleDirectLight(ShadingPoint sp, float pickU, inout uint rng) {
    LightPick pick = pickLight(sp.surface.position, sp.frame.n, pickU, rng);
    if (pick.ref == PN_NO_LIGHT) return vec3(0.0);
    return shadeLightSample(sp, sampleChosenLight(pick, sp.surface.position, sp.frame.n, rng));
}

// pixelIndex and sampleIndex stratify the light picks of this pixel's samples (one R1 sequence
// per path depth): a scene with a few lights gets each in its share of the samples.
vec3 radiance(vec3 origin, vec3 direction, uint pixelIndex, uint sampleIndex, inout uint rng) {
    vec3 result = vec3(0.0);
    vec3 throughput = vec3(1.0);
    float bsdfPdfPrev = 0.0;  // solid-angle pdf of the direction that led here
    bool afterDelta = true;   // the camera ray, or a delta lobe: light sampling could not see this
    vec3 medium = vec3(0.0);  // absorption coefficient of the medium the ray travels in
    vec3 previousNormal = vec3(0.0);    // shading normal where the current direction was sampled
    vec3 previousPosition = vec3(0.0);  // and the surface point there (what light sampling saw)
    for (uint depth = 0u;; ++depth) {
        ++closestRays;
        Hit hit = traceClosest(origin, direction, PN_INFINITY);
        if (hit.triangle == PN_NO_HIT) {
            // Escaping inside an absorbing medium (an open mesh) leaves nothing.
            if (medium == vec3(0.0))
                result += throughput * escapedRadiance(previousPosition, previousNormal, direction, afterDelta ? 0.0 : bsdfPdfPrev);
            break;
        }
        if (PN_HAS(PN_FEATURE_ABSORPTION)) throughput *= exp(-medium * hit.t);
        Surface s = surfaceAt(hit, origin, direction);
        Material m = materials[s.material];

        if ((m.flags & PN_MATERIAL_EMISSIVE) != 0u && s.frontFace) {
            float lightPdf = 0.0;
            if (!afterDelta && s.lightIndex != PN_NO_LIGHT && misSamplesLights())
                lightPdf = emitterHitPdf(hit, s, previousPosition, previousNormal, origin, direction);
            result += throughput * emittedRadiance(m, s.uv, direction, depth == 0u) * misWeightHit(bsdfPdfPrev, lightPdf, afterDelta);
        }
        if (depth >= frame.maxBounces) break;

        ShadingPoint sp;
        sp.surface = s;
        sp.frame = shadingFrameAt(s, m, hit.triangle, -direction);
        sp.bsdf = materialBsdf(m, s.uv, s.frontFace);
        sp.wo = toLocal(sp.frame, -direction);
        sp.mediumAbove = medium;
        // Refraction leaves the medium through a back face and enters the material's through a front one.
        sp.mediumBelow = PN_HAS(PN_FEATURE_ABSORPTION) && s.frontFace ? m.absorption : vec3(0.0);

        float pickU = stratifiedSample(pixelIndex, depth, sampleIndex, frame.seed);
        result += throughput * sampleDirectLight(sp, pickU, rng);

        vec3 u = vec3(rngNext2(rng), rngNext(rng));
        BsdfSample bs = bsdfSample(sp.bsdf, sp.wo, u);
        if (!(bs.pdf > 0.0) || max(bs.weight.r, max(bs.weight.g, bs.weight.b)) <= 0.0) break;
        vec3 wi = toWorld(sp.frame, bs.wi);
        // A sample on the other side of the true surface than the shading frame says would leak
        // light through it (or carry none): the path ends.
        bool above = dot(wi, s.geometricNormal) > 0.0;
        if (above != (bs.wi.z > 0.0)) break;
        throughput *= bs.weight;
        bsdfPdfPrev = bs.pdf;
        afterDelta = bs.isDelta;
        if (!above) medium = sp.mediumBelow;

        if (depth + 1u >= frame.rouletteStart) {
            float survive = min(max(throughput.r, max(throughput.g, throughput.b)), 1.0);
            if (rngNext(rng) >= survive) break;
            throughput /= survive;
        }
        origin = leavingOrigin(s, wi);
        direction = wi;
        previousNormal = sp.frame.n;
        previousPosition = s.position;
    }
    return result;
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy + uvec2(push.tileX, push.tileY);
    // Adaptive sampling (render/adaptive.h): a pixel whose mask entry is 0 takes no samples this
    // pass. Whole tiles share an entry, so the threads of a workgroup mostly agree and skip together.
    bool sampled = pixel.x < frame.width && pixel.y < frame.height;
    if (sampled && (push.mode & PN_TRACE_MASKED) != 0u) sampled = activeMask[pixel.y * frame.width + pixel.x] != 0u;
    if (sampled) {
        uint pixelIndex = pixel.y * frame.width + pixel.x;
        vec3 sum = vec3(0.0);
        float sumSquares = 0.0;
        for (uint s = 0u; s < frame.samplesPerPass; ++s) {
            uint rng = rngSeed(pixelIndex, push.passIndex * frame.samplesPerPass + s, frame.seed);
            vec2 jitter = rngNext2(rng);
            vec3 cameraOrigin, cameraDirection;
            cameraRay(vec2(pixel) + jitter, rng, cameraOrigin, cameraDirection);
            vec3 L = radiance(cameraOrigin, cameraDirection, pixelIndex, push.passIndex * frame.samplesPerPass + s, rng);
            // A NaN or inf sample would poison the pixel forever: it is dropped, and counted so
            // that tests (and the render summary) see it.
            if (any(isnan(L)) || any(isinf(L))) {
                L = vec3(0.0);
                atomicAdd(counters.invalidSamples, 1u);
            }
            sum += L;
            float y = luminance(L);
            sumSquares += y * y;
        }
        accum[pixelIndex] += vec4(sum, sumSquares);
    }
    if (push.countRays != 0u) {
        uint closest = subgroupAdd(closestRays);
        uint shadow = subgroupAdd(shadowRays);
        if (subgroupElect()) {
            atomicAdd(counters.closestRays, closest);
            atomicAdd(counters.shadowRays, shadow);
        }
    }
}
