// The local frame BSDFs work in: z is the shading normal (normal-mapped, and bent so the viewer
// is never below it), on the side the ray came from. Include after surface.glsl and textures.glsl.
#ifndef PN_SHADING_FRAME_GLSL
#define PN_SHADING_FRAME_GLSL

#include "lib/sampling.glsl"

struct ShadingFrame {
    vec3 t;
    vec3 b;
    vec3 n;
};

vec3 toLocal(ShadingFrame f, vec3 v) { return vec3(dot(v, f.t), dot(v, f.b), dot(v, f.n)); }
vec3 toWorld(ShadingFrame f, vec3 v) { return v.x * f.t + v.y * f.b + v.z * f.n; }

ShadingFrame frameAround(vec3 n) {
    ShadingFrame f;
    f.n = n;
    basisAround(n, f.t, f.b);
    return f;
}

// The normal map's normal at the hit, in world space on the winding's front side, or `front`
// unchanged when there is no map or no usable UV parameterisation. The tangent frame comes from
// the triangle's UV derivatives (no per-vertex tangents); the map's +y is up in the image, which
// is -v in our top-row-first UVs (glTF's convention).
// instance: Surface.instance (the triangle's edges are then in that instance's object space).
vec3 normalMapped(Material m, uint triangle, uint instance, vec2 uv, vec3 front) {
    if (!PN_HAS(PN_FEATURE_NORMAL_MAPS) || m.normalTexture == PN_NO_TEXTURE || triangle >= frame.triCount) return front;
    TriVerts tv = triVerts[triangle];
    if ((tv.flags & PN_TRI_SPHERE) != 0u) return front;  // spheres have no triangle UV frame
    TriUvs uvs = triUvs[tv.uvIndex];
    vec2 duv1 = uvs.uv1 - uvs.uv0, duv2 = uvs.uv2 - uvs.uv0;
    float det = duv1.x * duv2.y - duv1.y * duv2.x;
    if (abs(det) < 1e-12) return front;
    vec3 dpdu = (tv.e1 * duv2.y - tv.e2 * duv1.y) / det;
    vec3 dpdv = (tv.e2 * duv1.x - tv.e1 * duv2.x) / det;
    if (PN_HAS(PN_FEATURE_INSTANCES) && instance != PN_NO_HIT) {
        dpdu = instanceVectorToWorld(instance, dpdu);
        dpdv = instanceVectorToWorld(instance, dpdv);
    }
    vec3 t = dpdu - front * dot(front, dpdu);
    if (dot(t, t) < 1e-20) return front;
    t = normalize(t);
    // The bitangent follows -dpdv (image up), so mirrored UVs keep the right handedness.
    vec3 b = cross(front, t);
    if (dot(b, dpdv) > 0.0) b = -b;
    vec3 c = sampleTexture(m.normalTexture, uv, m.normalWrap).rgb * 2.0 - 1.0;
    vec3 n = c.x * t + c.y * b + max(c.z, 0.0) * front;
    return dot(n, n) > 1e-12 ? normalize(n) : front;
}

// The shading frame at s for a ray arriving from wo (world, pointing away from the surface).
ShadingFrame shadingFrameAt(Surface s, Material m, uint triangle, vec3 wo) {
    // Normal maps are authored for the front face; mirror them for back-face hits.
    vec3 front = s.frontFace ? s.shadingNormal : -s.shadingNormal;
    vec3 n = normalMapped(m, triangle, s.instance, s.uv, front);
    if (!s.frontFace) n = -n;
    if (dot(n, s.geometricNormal) < 0.0) n = reflect(n, s.geometricNormal);
    // A viewer below the shading normal (grazing views of bent normals) would see a black
    // BSDF; tilt the normal toward wo just enough, which is continuous and so leaves no seam.
    const float minCos = 1e-3;
    float c = dot(n, wo);
    if (c < minCos) n = normalize(n + (minCos - c) / max(1.0 - c * c, 1e-6) * (wo - c * n));
    return frameAround(n);
}

#endif
