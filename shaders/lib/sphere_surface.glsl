// The Surface at a hit on a sphere slot (PN_TRI_SPHERE: v0 = centre, e1.x = radius).
// Included by surface.glsl after the Surface struct.
#ifndef PN_SPHERE_SURFACE_GLSL
#define PN_SPHERE_SURFACE_GLSL

#include "lib/sampling.glsl"

// Longitude around +y (u = 0.5 toward +x) and colatitude from the +y pole (v = 0 at the top,
// as image rows run), so a texture wraps once around the sphere.
vec2 sphereUv(vec3 n) {
    return vec2(atan(n.z, n.x) * (0.5 * PN_INV_PI) + 0.5, acos(clamp(n.y, -1.0, 1.0)) * PN_INV_PI);
}

Surface sphereSurfaceAt(TriVerts tv, TriAttribs ta, float t, vec3 o, vec3 d) {
    float radius = tv.e1.x;
    // The outward normal from the hit, and the hit re-projected onto the sphere (as pbrt does):
    // the error of o + t d grows with t, the projection's only with the sphere's own size.
    vec3 n = normalize(o + t * d - tv.v0);
    Surface s;
    s.position = tv.v0 + radius * n;
    // The outside is the front (emitting) face; a ray from inside meets the back face, and the
    // normal then points inward, to the ray's side, so offsets move along the ray's side too.
    s.frontFace = dot(n, d) < 0.0;
    s.geometricNormal = s.frontFace ? n : -n;
    s.shadingNormal = s.geometricNormal;
    s.material = ta.materialId;
    s.lightIndex = ta.lightIndex;
    s.area = ta.area;
    s.uv = sphereUv(n);
    return s;
}

#endif
