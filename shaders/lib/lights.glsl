// Sampling one light once it is chosen: a point uniform over an emissive triangle, and the light a
// punctual light sends to a point. Choosing which light is lib/light_sampler.glsl's job.
#ifndef PN_LIGHTS_GLSL
#define PN_LIGHTS_GLSL

#include "lib/material.glsl"
#include "lib/sampling.glsl"

struct TrianglePoint {
    vec3 position;
    vec3 normal;     // front (emitting) side
    vec3 radiance;   // zero where an alpha-tested emitter has a hole (rays pass through there)
    float area;
};

// A point uniform over the area of primitive slot `tri` (an emissive triangle).
TrianglePoint sampleTrianglePoint(uint tri, vec2 u) {
    TriVerts tv = triVerts[tri];
    TriAttribs ta = triAttribs[tri];
    vec2 b = sampleTriangleUniform(u);
    Material m = materials[ta.materialId];
    TrianglePoint tp;
    tp.position = tv.v0 + b.x * tv.e1 + b.y * tv.e2;
    tp.normal = normalize(cross(tv.e1, tv.e2));
    tp.area = ta.area;
    bool hole = (tv.flags & PN_TRI_ALPHA_TESTED) != 0u && isAlphaHole(tri, tv, b.x, b.y);
    tp.radiance = hole ? vec3(0.0) : materialEmission(m, interpolateUv(tv, b.x, b.y));
    return tp;
}

// Light from punctual light `l` arriving at p: direction to it, distance, and the radiant
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

#endif
