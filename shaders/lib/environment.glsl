// Light from infinitely far away: an equirectangular environment map (or the constant
// background), importance sampled. Rays that escape are weighed against light sampling in
// lib/light_sampler.glsl. Include after scene_bindings.glsl.
//
// The map is looked up with the nearest texel, which keeps the lookup exactly proportional to
// the pdf: texel i is picked with probability pmf_i from an alias table (luminance x solid
// angle) and a direction drawn uniformly over its solid angle (uniform in phi and cos theta),
// so the solid-angle pdf inside texel i is the constant pmf_i / solidAngle_i stored with it.
// Map-local direction of (u, v): (sin theta sin phi, cos theta, -sin theta cos phi) with
// phi = 2 pi (u - 0.5), theta = pi v (src/scene/environment.h has the same mapping).
#ifndef PN_ENVIRONMENT_GLSL
#define PN_ENVIRONMENT_GLSL

#include "lib/sampling.glsl"
#include "lib/rng.glsl"

layout(std430, set = 0, binding = PN_BINDING_ENV_TABLE) readonly buffer EnvTableBuffer { EnvAlias envTable[]; };
layout(std430, set = 0, binding = PN_BINDING_ENV_TEXELS) readonly buffer EnvTexelBuffer { vec4 envTexels[]; };

struct EnvSample {
    vec3 direction;  // world space, unit
    vec3 radiance;   // intensity included
    float pdf;       // solid angle
};

// World <-> map frame: the map is turned by envRotation about +y.
vec3 envWorldToMap(vec3 d) {
    float c = cos(frame.envRotation), s = sin(frame.envRotation);
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}
vec3 envMapToWorld(vec3 d) {
    float c = cos(frame.envRotation), s = sin(frame.envRotation);
    return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

uint envTexelIndex(vec3 worldDirection) {
    vec3 d = envWorldToMap(worldDirection);
    // atan(0, 0) is undefined: straight up or down, any column will do.
    float u = (d.x == 0.0 && d.z == 0.0) ? 0.5 : atan(d.x, -d.z) * (0.5 * PN_INV_PI) + 0.5;
    float v = acos(clamp(d.y, -1.0, 1.0)) * PN_INV_PI;
    uint x = min(uint(max(u, 0.0) * float(frame.envWidth)), frame.envWidth - 1u);
    uint y = min(uint(max(v, 0.0) * float(frame.envHeight)), frame.envHeight - 1u);
    return y * frame.envWidth + x;
}

vec3 environmentRadiance(vec3 direction) {
    if (!PN_HAS(PN_FEATURE_ENV_MAP) || frame.envWidth == 0u) return frame.background * frame.envIntensity;
    return envTexels[envTexelIndex(direction)].rgb * frame.envIntensity;
}

// Solid-angle pdf with which sampleEnvironment(n, ...) returns `direction`.
float environmentPdf(vec3 direction, vec3 n) {
    if (!PN_HAS(PN_FEATURE_ENV_MAP) || frame.envWidth == 0u) return max(dot(n, direction), 0.0) * PN_INV_PI;
    return envTable[envTexelIndex(direction)].pdf;
}

// A direction toward the environment as seen from a surface of shading normal n (the map's
// sampling ignores n).
EnvSample sampleEnvironment(vec3 n, inout uint rng) {
    EnvSample es;
    if (!PN_HAS(PN_FEATURE_ENV_MAP) || frame.envWidth == 0u) {
        // The constant background: cosine-weighted around n, the distribution of its
        // contribution to any diffuse surface (for a Lambertian BSDF, MIS then gives every
        // unoccluded sample the exact answer).
        es.direction = sampleCosineHemisphere(n, rngNext2(rng));
        es.radiance = frame.background * frame.envIntensity;
        es.pdf = max(dot(n, es.direction), 0.0) * PN_INV_PI;
        return es;
    }
    uint count = frame.envWidth * frame.envHeight;
    // The slot from all 32 random bits (floor(bits * count / 2^32)): a float has too few bits
    // to reach every texel of a large map.
    uint slot, low;
    umulExtended(rngNextUint(rng), count, slot, low);
    EnvAlias entry = envTable[slot];
    uint texel = rngNext(rng) < entry.threshold ? slot : entry.alias;
    uint x = texel % frame.envWidth, y = texel / frame.envWidth;
    vec2 u = rngNext2(rng);
    float phi = 2.0 * PN_PI * ((float(x) + u.x) / float(frame.envWidth)) - PN_PI;
    float cos0 = cos(PN_PI * float(y) / float(frame.envHeight));
    float cos1 = cos(PN_PI * float(y + 1u) / float(frame.envHeight));
    float cosTheta = mix(cos0, cos1, u.y);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    es.direction = envMapToWorld(vec3(sinTheta * sin(phi), cosTheta, -sinTheta * cos(phi)));
    es.radiance = envTexels[texel].rgb * frame.envIntensity;
    es.pdf = envTable[texel].pdf;
    return es;
}

#endif
