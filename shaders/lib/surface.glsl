// What a closest hit needs for shading, gathered once from the cold triangle data.
#ifndef PN_SURFACE_GLSL
#define PN_SURFACE_GLSL

struct Surface {
    vec3 position;
    vec3 geometricNormal;  // unit, facing the side the ray came from
    vec3 shadingNormal;    // unit, on the same side as geometricNormal
    bool frontFace;        // the ray hit the side the winding order calls front (the emitting side)
    uint material;
    uint lightIndex;  // LightRef of an emitter (PN_NO_LIGHT: none), for MIS on hits
    float area;
    vec2 uv;
};

#include "lib/sphere_surface.glsl"
#include "lib/sprite_surface.glsl"

Surface surfaceAt(Hit hit, vec3 o, vec3 d) {
    TriVerts tv = triVerts[hit.triangle];
    TriAttribs ta = triAttribs[hit.triangle];
    if (PN_HAS(PN_FEATURE_SPHERES) && (tv.flags & PN_TRI_SPHERE) != 0u) return sphereSurfaceAt(tv, ta, hit.t, o, d);
    if (PN_HAS(PN_FEATURE_SPRITES) && (tv.flags & PN_TRI_SPRITE) != 0u) return spriteSurfaceAt(tv, ta, hit.t, hit.u, hit.v, o, d);
    Surface s;
    s.position = o + hit.t * d;
    vec3 ng = normalize(cross(tv.e1, tv.e2));
    s.frontFace = dot(ng, d) < 0.0;
    s.geometricNormal = s.frontFace ? ng : -ng;
    vec3 ns = normalize((1.0 - hit.u - hit.v) * ta.n0 + hit.u * ta.n1 + hit.v * ta.n2);
    // Interpolated normals may lean to the far side of the geometry; keep them on the ray's side.
    if (dot(ns, s.geometricNormal) < 0.0) ns = -ns;
    s.shadingNormal = ns;
    s.material = ta.materialId;
    s.lightIndex = ta.lightIndex;
    s.area = ta.area;
    s.uv = interpolateUv(ta, hit.u, hit.v);
    return s;
}

#endif
