// Sphere lights (emissive spheres and spot lights with a radius, FrameUniforms.sphereLightCount
// of them; lib/light_sampler.glsl chooses one), sampled uniformly over the cone of directions the
// sphere subtends: every sample is a point the shading point can see, and the pdf is the constant
// 1 / (2 pi (1 - cos theta_max)). From inside a sphere there is no cone; there the sample is
// uniform over the sphere's area instead.
#ifndef PN_SPHERE_LIGHTS_GLSL
#define PN_SPHERE_LIGHTS_GLSL

#include "lib/sampling.glsl"

struct SphereLightSample {
    vec3 wi;         // unit, from the shading point toward the light
    vec3 position;   // the sampled point, on the side of the sphere the shading point sees
    vec3 normal;     // outward, at position
    vec3 radiance;   // arriving along -wi (a spot light's cone falloff applied)
    float pdf;       // solid angle (the light's selection probability not included); 0: no sample
    bool lightOnly;  // no geometry (a spot light): BSDF sampling never reaches it, so no MIS
};

// 1 - cos(theta_max) of the cone subtended by a sphere with sin^2(theta_max) = sin2, written so
// that it keeps its digits for distant, small spheres (1 - sqrt(1 - x) cancels for small x).
float sphereConeOneMinusCos(float sin2) { return sin2 / (1.0 + sqrt(max(0.0, 1.0 - sin2))); }

// Solid-angle density with which sampleSphereLight draws a direction from p that meets the
// sphere (centre c, radius r) at distance tHit with |cos| cosHit at the surface, excluding the
// selection probability. Must agree with the sampler, for MIS on BSDF-sampled hits.
float sphereDirectionPdf(vec3 c, float r, vec3 p, float tHit, float cosHit) {
    vec3 pc = c - p;
    float dc2 = dot(pc, pc);
    float r2 = r * r;
    if (dc2 <= r2) return tHit * tHit / (max(cosHit, 1e-12) * 4.0 * PN_PI * r2);
    return 1.0 / (2.0 * PN_PI * sphereConeOneMinusCos(r2 / dc2));
}

SphereLightSample sampleSphereLight(SphereLight l, vec3 p, vec2 u) {
    SphereLightSample ls;
    ls.pdf = 0.0;
    ls.lightOnly = l.primitive == PN_NO_HIT;

    vec3 pc = l.center - p;
    float dc2 = dot(pc, pc);
    float r2 = l.radius * l.radius;
    if (dc2 <= r2) {
        // Inside: uniform over the area. Only the outside emits, so this finds no light, but it
        // keeps the estimator defined (and the pdf matches sphereDirectionPdf).
        float z = 1.0 - 2.0 * u.x;
        float ring = sqrt(max(0.0, 1.0 - z * z));
        float phi = 2.0 * PN_PI * u.y;
        ls.normal = vec3(ring * cos(phi), ring * sin(phi), z);
        ls.position = l.center + l.radius * ls.normal;
        vec3 toPoint = ls.position - p;
        float dist2 = dot(toPoint, toPoint);
        if (!(dist2 > 0.0)) return ls;
        ls.wi = toPoint * inversesqrt(dist2);
        ls.radiance = vec3(0.0);  // the inside is the back face
        ls.pdf = sphereDirectionPdf(l.center, l.radius, p, sqrt(dist2), abs(dot(ls.normal, ls.wi)));
        return ls;
    }

    // Uniform in the cone around the axis to the centre: theta from cos uniform in
    // [cos theta_max, 1], then the point where that direction first meets the sphere, found by
    // the angle alpha at the centre (pbrt-v4's construction, which avoids a ray-sphere test).
    float dc = sqrt(dc2);
    float sin2Max = r2 / dc2;
    float sinMax = sqrt(sin2Max);
    float oneMinusCosMax = sphereConeOneMinusCos(sin2Max);
    float oneMinusCos = u.x * oneMinusCosMax;
    float cosTheta = 1.0 - oneMinusCos;
    float sin2Theta = oneMinusCos * (2.0 - oneMinusCos);
    float cosAlpha = sin2Theta / sinMax + cosTheta * sqrt(max(0.0, 1.0 - sin2Theta / sin2Max));
    float sinAlpha = sqrt(max(0.0, 1.0 - cosAlpha * cosAlpha));
    float phi = 2.0 * PN_PI * u.y;
    vec3 axis = pc / dc;
    vec3 t, b;
    basisAround(axis, t, b);
    ls.normal = -(sinAlpha * cos(phi) * t + sinAlpha * sin(phi) * b + cosAlpha * axis);
    ls.position = l.center + l.radius * ls.normal;
    ls.wi = normalize(ls.position - p);
    ls.pdf = 1.0 / (2.0 * PN_PI * oneMinusCosMax);
    ls.radiance = l.radiance;
    if (ls.lightOnly) {
        // A spot light's cone, by the direction from its centre to the shading point.
        float cd = dot(l.spotDirection, -axis);
        ls.radiance *= smoothstep(l.cosOuter, max(l.cosInner, l.cosOuter + 1e-4), cd);
    }
    return ls;
}

#endif
