// Light sampling: an emissive triangle chosen from the alias table (in proportion to power),
// then a point uniform over its area.
#ifndef PN_LIGHTS_GLSL
#define PN_LIGHTS_GLSL

#include "lib/material.glsl"
#include "lib/sampling.glsl"

struct LightSample {
    vec3 position;
    vec3 normal;     // front (emitting) side
    vec3 radiance;
    float pdfArea;   // pmf of the triangle / its area (the triangle table's share included)
};

// A point on an emissive triangle chosen by power. Triangle and punctual lights are each sampled
// at every vertex, so neither class's share of samples has to be guessed.
LightSample sampleLight(inout uint rng) {
    float u = rngNext(rng) * float(frame.lightCount);
    uint slot = min(uint(u), frame.lightCount - 1u);
    LightAlias entry = lights[slot];
    if (fract(u) >= entry.threshold) entry = lights[entry.alias];
    TriVerts tv = triVerts[entry.triangle];
    TriAttribs ta = triAttribs[entry.triangle];
    vec2 b = sampleTriangleUniform(rngNext2(rng));
    LightSample ls;
    ls.position = tv.v0 + b.x * tv.e1 + b.y * tv.e2;
    ls.normal = normalize(cross(tv.e1, tv.e2));
    ls.radiance = materialEmission(materials[ta.materialId], interpolateUv(ta, b.x, b.y));
    ls.pdfArea = entry.pmf / ta.area;
    return ls;
}

// Light from punctual light `index` arriving at p: direction to it, distance, and the radiant
// intensity falling on p (already divided by distance squared and windowed by range and cone).
vec3 punctualIncident(PunctualLight l, vec3 p, out vec3 wi, out float dist) {
    if (l.type == PN_LIGHT_DIRECTIONAL) {
        wi = -l.direction;
        dist = PN_INFINITY;
        return l.intensity;
    }
    vec3 d = l.position - p;
    float dist2 = max(dot(d, d), 1e-12);
    dist = sqrt(dist2);
    wi = d / dist;
    float falloff = 1.0 / dist2;
    if (l.range > 0.0) {
        float x = dist / l.range;
        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        falloff *= window * window;
    }
    if (l.type == PN_LIGHT_SPOT) {
        float cd = dot(l.direction, -wi);
        falloff *= smoothstep(l.cosOuter, max(l.cosInner, l.cosOuter + 1e-4), cd);
    }
    return l.intensity * falloff;
}

// How much light `l` could bring to p (ignoring visibility and the surface's orientation).
float punctualWeight(PunctualLight l, vec3 p) {
    if (frame.punctualCount > PN_PUNCTUAL_SCAN_LIMIT) return l.selectPmf;
    vec3 wi;
    float dist;
    return dot(punctualIncident(l, p, wi, dist), vec3(0.2126, 0.7152, 0.0722));
}

// Picks a punctual light in proportion to punctualWeight at p; pmf is its probability (0 when
// no light reaches p at all).
uint pickPunctual(vec3 p, float u, out float pmf) {
    float total = 0.0;
    for (uint i = 0u; i < frame.punctualCount; ++i) total += punctualWeight(punctualLights[i], p);
    pmf = 0.0;
    if (!(total > 0.0)) return 0u;
    float target = u * total, acc = 0.0;
    uint last = 0u;
    for (uint i = 0u; i < frame.punctualCount; ++i) {
        float w = punctualWeight(punctualLights[i], p);
        if (w <= 0.0) continue;
        last = i;
        pmf = w / total;
        acc += w;
        if (target < acc) return i;
    }
    return last;  // rounding left target at the very top: the last light with weight
}

#endif
