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
    uint instance;  // Hit.instance: the space the triangle data is in (PN_NO_HIT: world)
};

#include "shared/unit_vector.h"
#include "lib/sphere_surface.glsl"
#include "lib/sprite_surface.glsl"

// An object-space normal of an instance in world space: by the inverse transpose (the transpose
// of worldToObject's linear part), unit length.
vec3 instanceNormalToWorld(uint instance, vec3 n) {
    return normalize(n.x * instances[instance].worldToObject[0].xyz + n.y * instances[instance].worldToObject[1].xyz +
                     n.z * instances[instance].worldToObject[2].xyz);
}

// An object-space vector of an instance (an edge, a tangent) in world space.
vec3 instanceVectorToWorld(uint instance, vec3 v) {
    return vec3(dot(instances[instance].objectToWorld[0].xyz, v), dot(instances[instance].objectToWorld[1].xyz, v),
                dot(instances[instance].objectToWorld[2].xyz, v));
}

// o and d: the world ray. Spheres and sprites are only ever in the world's own level (whose
// instance, when there are instances, is the identity), so their data is world space.
Surface surfaceAt(Hit hit, vec3 o, vec3 d) {
    TriVerts tv = triVerts[hit.triangle];
    TriAttribs ta = triAttribs[hit.triangle];
    Surface s;
    if (PN_HAS(PN_FEATURE_SPHERES) && (tv.flags & PN_TRI_SPHERE) != 0u) {
        s = sphereSurfaceAt(tv, ta, hit.t, o, d);
        s.instance = PN_NO_HIT;
        return s;
    }
    if (PN_HAS(PN_FEATURE_SPRITES) && (tv.flags & PN_TRI_SPRITE) != 0u) {
        s = spriteSurfaceAt(tv, ta, hit.t, hit.u, hit.v, o, d);
        s.instance = PN_NO_HIT;
        return s;
    }
    s.instance = hit.instance;
    s.position = o + hit.t * d;
    vec3 ng = normalize(cross(tv.e1, tv.e2));
    vec3 ns = normalize((1.0 - hit.u - hit.v) * unpackUnitVector(ta.n0) + hit.u * unpackUnitVector(ta.n1) +
                        hit.v * unpackUnitVector(ta.n2));
    if (PN_HAS(PN_FEATURE_INSTANCES) && hit.instance != PN_NO_HIT) {
        ng = instanceNormalToWorld(hit.instance, ng);
        ns = instanceNormalToWorld(hit.instance, ns);
    }
    s.frontFace = dot(ng, d) < 0.0;
    s.geometricNormal = s.frontFace ? ng : -ng;
    // Interpolated normals may lean to the far side of the geometry; keep them on the ray's side.
    if (dot(ns, s.geometricNormal) < 0.0) ns = -ns;
    s.shadingNormal = ns;
    s.material = ta.materialId;
    s.lightIndex = ta.lightIndex;
    s.area = ta.area;
    s.uv = interpolateUv(tv, hit.u, hit.v);
    return s;
}

#endif
