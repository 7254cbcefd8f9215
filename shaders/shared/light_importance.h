// The light BVH's importance bound (Conty Estevez & Kulla 2018; pbrt-v4's LightBounds::Importance):
// how much a cluster of lights could bring to a shading point. The shaders weigh tree nodes with
// it at every pick (lib/light_sampler.glsl); the host weighs them for whole grid cells and bins of
// normals (render/light_grid.cpp), widening the same bound. Valid GLSL and C++; include after
// shared/types.h.
#ifndef PENUMBRA_SHADER_LIGHT_IMPORTANCE_H
#define PENUMBRA_SHADER_LIGHT_IMPORTANCE_H

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
namespace penumbra::shader {
using std::abs;
using std::max;
using std::min;
using std::sqrt;
inline float inversesqrt(float x) { return 1.0f / std::sqrt(x); }
#endif
#include "shared/inline.h"

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of angles a, b in [0, pi].
PN_INLINE float cosSubClamped(float sinA, float cosA, float sinB, float cosB) { return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB; }
PN_INLINE float sinSubClamped(float sinA, float cosA, float sinB, float cosB) { return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB; }

PN_INLINE float sinFromCos(float c) { return sqrt(max(0.0f, 1.0f - c * c)); }

// Bounds of a set of lights: a sphere holding them, their power, and the cones of their normals
// (thetaO about axis) and of their emission beyond a normal (thetaE).
struct LightCluster {
    vec3 center;
    float radius;
    vec3 axis;
    float phi;
    float cosThetaO, sinThetaO, cosThetaE;
    bool twoSided;
};

// How much the lights of cluster c could bring to a surface at p whose normal lies within an
// angle (sine sinN, cosine cosN) of n (sinN 0, cosN 1: the normal is n; n = 0: no surface): zero
// only where they cannot light it at all. `widened` false compiles the angle out (the shaders'
// exact points).
PN_INLINE float clusterImportanceWithin(LightCluster c, vec3 p, vec3 n, bool widened, float sinN, float cosN) {
    vec3 toP = p - c.center;
    float dist2 = dot(toP, toP);
    float invDist = inversesqrt(dist2);
    vec3 wi = dist2 > 0.0f ? toP * invDist : c.axis;
    float cosW = dot(c.axis, wi);
    if (c.twoSided) cosW = abs(cosW);
    float sinW = sinFromCos(cosW);
    // The cone from p that holds the sphere; every direction from inside it.
    bool outside = dist2 > c.radius * c.radius;
    float sinB = outside ? c.radius * invDist : 0.0f;
    float cosB = outside ? sqrt(max(0.0f, 1.0f - sinB * sinB)) : -1.0f;
    // The smallest angle between an emitting normal and a direction toward p, then the emission
    // spread beyond it.
    float cosX = cosSubClamped(sinW, cosW, c.sinThetaO, c.cosThetaO);
    float sinX = sinSubClamped(sinW, cosW, c.sinThetaO, c.cosThetaO);
    float cosP = cosSubClamped(sinX, cosX, sinB, cosB);
    if (cosP <= c.cosThetaE) return 0.0f;
    // Within the bounds the squared distance says little; pbrt-v4 floors it at half the diagonal.
    float importance = c.phi * cosP / max(dist2, c.radius);
    if (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f) {
        // The cosine at the surface, either side (transmission), bounded over the sphere's cone
        // (and over the cone of normals: the two angles add, up to pi).
        float cosI = abs(dot(wi, n));
        float cosS = cosB, sinS = sinB;
        if (widened) {
            cosS = cosB * cosN - sinB * sinN;
            sinS = cosB > -cosN ? sinB * cosN + cosB * sinN : 0.0f;
            if (!(cosB > -cosN)) cosS = -1.0f;
        }
        importance *= cosSubClamped(sinFromCos(cosI), cosI, sinS, cosS);
    }
    return max(importance, 0.0f);
}

PN_INLINE float clusterImportance(LightCluster c, vec3 p, vec3 n) { return clusterImportanceWithin(c, p, n, false, 0.0f, 1.0f); }

// The light grid's table (render/light_grid.h) for a point at grid coordinates g ((p - origin) /
// cell size) with shading normal n: cell (x fastest) times PN_LIGHT_GRID_BINS plus n's bin, its
// largest component's axis and sign. PN_NO_HIT off the grid (NaN included) or without a normal.
PN_INLINE uint lightGridTableIndex(vec3 g, uint dimX, uint dimY, uint dimZ, vec3 n) {
    if (!(g.x >= 0.0f && g.y >= 0.0f && g.z >= 0.0f && g.x < float(dimX) && g.y < float(dimY) && g.z < float(dimZ)))
        return PN_NO_HIT;
    if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) return PN_NO_HIT;
    uint x = min(uint(g.x), dimX - 1u), y = min(uint(g.y), dimY - 1u), z = min(uint(g.z), dimZ - 1u);
    float ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
    uint bin = ax >= ay && ax >= az ? (n.x < 0.0f ? 1u : 0u) : (ay >= az ? (n.y < 0.0f ? 3u : 2u) : (n.z < 0.0f ? 5u : 4u));
    return ((z * dimY + y) * dimX + x) * PN_LIGHT_GRID_BINS + bin;
}

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
