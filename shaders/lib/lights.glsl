// Light sampling: an emissive triangle chosen from the alias table (in proportion to power),
// then a point uniform over its area.
#ifndef PN_LIGHTS_GLSL
#define PN_LIGHTS_GLSL

#include "lib/sampling.glsl"

struct LightSample {
    vec3 position;
    vec3 normal;     // front (emitting) side
    vec3 radiance;
    float pdfArea;   // pmf of the triangle / its area
};

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
    ls.radiance = materials[ta.materialId].emission;
    ls.pdfArea = entry.pmf / ta.area;
    return ls;
}

#endif
