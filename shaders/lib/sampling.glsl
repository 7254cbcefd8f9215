// Sampling routines and the power heuristic.
#ifndef PN_SAMPLING_GLSL
#define PN_SAMPLING_GLSL

#include "shared/constants.h"

// An orthonormal basis around unit n (Duff et al., "Building an Orthonormal Basis, Revisited").
void basisAround(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction around n by Malley's method (uniform disk, projected up);
// pdf = cos(theta) / pi.
vec3 sampleCosineHemisphere(vec3 n, vec2 u) {
    float r = sqrt(u.x);
    float phi = 2.0 * PN_PI * u.y;
    vec3 t, b;
    basisAround(n, t, b);
    float z = sqrt(max(0.0, 1.0 - u.x));
    return normalize(t * (r * cos(phi)) + b * (r * sin(phi)) + n * z);
}

// Barycentrics (b1, b2) uniform over a triangle's area.
vec2 sampleTriangleUniform(vec2 u) {
    float su = sqrt(u.x);
    return vec2(1.0 - su, u.y * su);
}

float powerHeuristic(float pdfA, float pdfB) {
    float a = pdfA * pdfA;
    float b = pdfB * pdfB;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

#endif
