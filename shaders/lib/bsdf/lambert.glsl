// The Lambertian BSDF: f = albedo / pi, sampled with a cosine-weighted hemisphere.
#ifndef PN_BSDF_LAMBERT_GLSL
#define PN_BSDF_LAMBERT_GLSL

#include "lib/sampling.glsl"

vec3 lambertEval(vec3 albedo) { return albedo * PN_INV_PI; }

float lambertPdf(vec3 n, vec3 wi) { return max(dot(n, wi), 0.0) * PN_INV_PI; }

#endif
