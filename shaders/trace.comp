#version 460
// The path tracer: one thread per pixel, samplesPerPass paths each, added into the accumulation
// buffer (rgb = sum of radiance, a = sum of squared luminance, for variance estimates).
// Unidirectional path tracing with next event estimation to emissive triangles and MIS (power
// heuristic) against BSDF sampling, so light reached either way is counted once.
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
#include "lib/lights.glsl"
#include "lib/environment.glsl"
#include "lib/bsdf/lambert.glsl"

layout(std430, set = 0, binding = PN_BINDING_ACCUM) buffer AccumBuffer { vec4 accum[]; };
layout(std430, set = 0, binding = PN_BINDING_COUNTERS) buffer CounterBuffer { RayCounters counters; };

uint closestRays = 0u;
uint shadowRays = 0u;

// Direct light from a sun disk (a directional light with an angular radius), MIS-weighted
// against the BSDF: escaped rays can hit it too.
vec3 sampleDirectSun(Surface s, vec3 albedo, PunctualLight l, float pickPmf, inout uint rng) {
    vec3 wi = sampleSunDisk(l, rngNext2(rng));
    float cosSurface = dot(s.shadingNormal, wi);
    if (cosSurface <= 0.0 || dot(s.geometricNormal, wi) <= 0.0 || !(pickPmf > 0.0)) return vec3(0.0);
    float lightPdf = pickPmf * sunConePdf(l);
    float weight = distantLightWeight(lightPdf, lambertPdf(s.shadingNormal, wi));
    if (weight <= 0.0) return vec3(0.0);
    ++shadowRays;
    if (traceOccluded(offsetRayOrigin(s.position, s.geometricNormal), wi, PN_INFINITY)) return vec3(0.0);
    return lambertEval(albedo) * cosSurface * sunRadiance(l) * (weight / lightPdf);
}

// Direct light from the environment (map or constant background), MIS-weighted against the BSDF.
vec3 sampleDirectEnvironment(Surface s, vec3 albedo, inout uint rng) {
    EnvSample es = sampleEnvironment(s.shadingNormal, rng);
    float cosSurface = dot(s.shadingNormal, es.direction);
    if (cosSurface <= 0.0 || dot(s.geometricNormal, es.direction) <= 0.0 || !(es.pdf > 0.0)) return vec3(0.0);
    float weight = distantLightWeight(es.pdf, lambertPdf(s.shadingNormal, es.direction));
    if (weight <= 0.0 || max(es.radiance.r, max(es.radiance.g, es.radiance.b)) <= 0.0) return vec3(0.0);
    ++shadowRays;
    if (traceOccluded(offsetRayOrigin(s.position, s.geometricNormal), es.direction, PN_INFINITY)) return vec3(0.0);
    return lambertEval(albedo) * cosSurface * es.radiance * (weight / es.pdf);
}

// Direct light from a punctual light (a delta light: no MIS, BSDF sampling never hits it).
vec3 sampleDirectPunctual(Surface s, vec3 albedo, inout uint rng) {
    float pmf;
    uint index = pickPunctual(s.position, rngNext(rng), pmf);
    PunctualLight l = punctualLights[index];
    if (isSunDisk(l)) return sampleDirectSun(s, albedo, l, pmf, rng);
    vec3 wi;
    float dist;
    vec3 incident = punctualIncident(l, s.position, wi, dist);
    float cosSurface = dot(s.shadingNormal, wi);
    if (cosSurface <= 0.0 || dot(s.geometricNormal, wi) <= 0.0 || !(pmf > 0.0) || max(incident.r, max(incident.g, incident.b)) <= 0.0)
        return vec3(0.0);
    vec3 origin = offsetRayOrigin(s.position, s.geometricNormal);
    ++shadowRays;
    if (traceOccluded(origin, wi, dist == PN_INFINITY ? PN_INFINITY : dist * (1.0 - 1e-4))) return vec3(0.0);
    return lambertEval(albedo) * cosSurface * incident / pmf;
}

// Direct light from an emissive triangle, MIS-weighted against the BSDF.
vec3 sampleDirectTriangle(Surface s, vec3 albedo, inout uint rng) {
    LightSample ls = sampleLight(rng);
    vec3 toLight = ls.position - s.position;
    float dist2 = dot(toLight, toLight);
    if (dist2 <= 0.0) return vec3(0.0);
    float dist = sqrt(dist2);
    vec3 wi = toLight / dist;
    float cosLight = -dot(ls.normal, wi);
    float cosSurface = dot(s.shadingNormal, wi);
    if (cosLight <= 0.0 || cosSurface <= 0.0 || dot(s.geometricNormal, wi) <= 0.0) return vec3(0.0);
    float lightPdf = ls.pdfArea * dist2 / cosLight;  // solid angle
    if (!(lightPdf > 0.0)) return vec3(0.0);

    vec3 origin = offsetRayOrigin(s.position, s.geometricNormal);
    vec3 target = offsetRayOrigin(ls.position, ls.normal);
    vec3 span = target - origin;
    float spanLength = length(span);
    ++shadowRays;
    // The shadow ray stops short of the light so it cannot hit the light itself.
    if (traceOccluded(origin, span / spanLength, spanLength * (1.0 - 1e-4))) return vec3(0.0);

    float weight = powerHeuristic(lightPdf, lambertPdf(s.shadingNormal, wi));
    return lambertEval(albedo) * cosSurface * ls.radiance * (weight / lightPdf);
}

vec3 radiance(vec3 origin, vec3 direction, inout uint rng) {
    vec3 result = vec3(0.0);
    vec3 throughput = vec3(1.0);
    float bsdfPdf = 0.0;  // solid-angle pdf of the direction that led here (0: camera ray)
    vec3 previousNormal = vec3(0.0);  // shading normal where that direction was sampled
    for (uint depth = 0u;; ++depth) {
        ++closestRays;
        Hit hit = traceClosest(origin, direction, PN_INFINITY);
        if (hit.triangle == PN_NO_HIT) {
            result += throughput * escapedRadiance(origin, previousNormal, direction, bsdfPdf);
            break;
        }
        Surface s = surfaceAt(hit, origin, direction);
        Material m = materials[s.material];

        if ((m.flags & PN_MATERIAL_EMISSIVE) != 0u && s.frontFace) {
            float weight = 1.0;
            if (depth > 0u && s.lightPmf > 0.0) {
                float cosLight = dot(s.geometricNormal, -direction);
                float lightPdf = s.lightPmf / s.area * hit.t * hit.t / max(cosLight, 1e-12);
                weight = powerHeuristic(bsdfPdf, lightPdf);
            }
            result += throughput * m.emission * weight;
        }
        if (depth >= frame.maxBounces) break;

        vec3 albedo = materialBaseColor(m, s.uv).rgb;
        if (frame.lightCount > 0u) result += throughput * sampleDirectTriangle(s, albedo, rng);
        if (frame.punctualCount > 0u) result += throughput * sampleDirectPunctual(s, albedo, rng);
        if (environmentIsLight()) result += throughput * sampleDirectEnvironment(s, albedo, rng);

        vec3 wi = sampleCosineHemisphere(s.shadingNormal, rngNext2(rng));
        // A sample under the true surface (possible with shading normals) carries no light.
        if (dot(wi, s.geometricNormal) <= 0.0) break;
        bsdfPdf = lambertPdf(s.shadingNormal, wi);
        if (!(bsdfPdf > 0.0)) break;
        throughput *= lambertEval(albedo) * dot(s.shadingNormal, wi) / bsdfPdf;

        if (depth + 1u >= frame.rouletteStart) {
            float survive = min(max(throughput.r, max(throughput.g, throughput.b)), 1.0);
            if (rngNext(rng) >= survive) break;
            throughput /= survive;
        }
        origin = offsetRayOrigin(s.position, s.geometricNormal);
        direction = wi;
        previousNormal = s.shadingNormal;
    }
    return result;
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x < frame.width && pixel.y < frame.height) {
        uint pixelIndex = pixel.y * frame.width + pixel.x;
        vec3 sum = vec3(0.0);
        float sumSquares = 0.0;
        for (uint s = 0u; s < frame.samplesPerPass; ++s) {
            uint rng = rngSeed(pixelIndex, push.passIndex * frame.samplesPerPass + s, frame.seed);
            vec2 jitter = rngNext2(rng);
            vec3 L = radiance(frame.cameraPosition, cameraRayDirection(vec2(pixel) + jitter), rng);
            // A NaN or inf sample would poison the pixel forever: it is dropped, and counted so
            // that tests (and the render summary) see it.
            if (any(isnan(L)) || any(isinf(L))) {
                L = vec3(0.0);
                atomicAdd(counters.invalidSamples, 1u);
            }
            sum += L;
            float y = dot(L, vec3(0.2126, 0.7152, 0.0722));
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
