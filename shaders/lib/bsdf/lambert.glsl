// The Lambertian BSDF: f = albedo / pi, sampled with a cosine-weighted hemisphere, in the shading
// frame (z = normal).
#ifndef PN_BSDF_LAMBERT_GLSL
#define PN_BSDF_LAMBERT_GLSL

#include "lib/sampling.glsl"

vec3 lambertEval(vec3 albedo) { return albedo * PN_INV_PI; }

float lambertPdfLocal(vec3 wi) { return max(wi.z, 0.0) * PN_INV_PI; }

vec3 lambertSampleLocal(vec2 u) {
    float r = sqrt(u.x);
    float phi = 2.0 * PN_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}

#endif
