// Directional lights with an angular radius (the sun): a disk of uniform radiance
// L = E / (pi sin^2 alpha) filling a cone of half-angle alpha around the direction toward the
// light, so that a surface facing it receives illuminance E, as from the delta light it
// replaces. Sampled uniformly over the cone's solid angle 2 pi (1 - cos alpha).
// Include after scene_bindings.glsl.
#ifndef PN_SUN_GLSL
#define PN_SUN_GLSL

#include "lib/sampling.glsl"

bool isSunDisk(PunctualLight l) { return l.type == PN_LIGHT_DIRECTIONAL && l.coneOneMinusCos > 0.0; }

float sunConePdf(PunctualLight l) { return 1.0 / (2.0 * PN_PI * l.coneOneMinusCos); }

// sin^2 alpha = (1 - cos)(1 + cos), in the form that keeps precision for tiny disks.
vec3 sunRadiance(PunctualLight l) {
    float c = l.coneOneMinusCos;
    return l.intensity / (PN_PI * c * (2.0 - c));
}

bool insideSunDisk(PunctualLight l, vec3 direction) { return 1.0 - dot(direction, -l.direction) <= l.coneOneMinusCos; }

// A direction uniform over the disk's cone.
vec3 sampleSunDisk(PunctualLight l, vec2 u) {
    float oneMinusCos = u.x * l.coneOneMinusCos;
    float cosTheta = 1.0 - oneMinusCos;
    float sinTheta = sqrt(max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    float phi = 2.0 * PN_PI * u.y;
    vec3 axis = -l.direction, t, b;
    basisAround(axis, t, b);
    return normalize(t * (sinTheta * cos(phi)) + b * (sinTheta * sin(phi)) + axis * cosTheta);
}

#endif
