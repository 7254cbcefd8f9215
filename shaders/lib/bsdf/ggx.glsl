// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, in the local shading frame
// (z = macro normal): D, Smith's height-correlated masking-shadowing G2, and sampling of the
// normals visible from a direction (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
#ifndef PN_BSDF_GGX_GLSL
#define PN_BSDF_GGX_GLSL

#include "lib/sampling.glsl"

float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    float c2 = h.z * h.z;
    float k = c2 * (a2 - 1.0) + 1.0;  // = cos^2 (a^2 + tan^2) / 1
    return a2 / (PN_PI * k * k);
}

// Smith's Lambda for GGX: the masking function is 1 / (1 + Lambda).
float ggxLambda(vec3 w, float alpha) {
    float c2 = w.z * w.z;
    if (c2 <= 0.0) return 1e30;
    float tan2 = max(0.0, 1.0 - c2) / c2;
    return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

float ggxG1(vec3 w, float alpha) { return 1.0 / (1.0 + ggxLambda(w, alpha)); }

// Height-correlated masking-shadowing (Heitz 2014): symmetric in wo and wi, so the BRDF built
// on it is reciprocal. Either direction may be below the surface (transmission): only |cos| counts.
float ggxG2(vec3 wo, vec3 wi, float alpha) {
    return 1.0 / (1.0 + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}

// A microfacet normal distributed as D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z, for wo.z > 0.
vec3 ggxSampleVisibleNormal(vec3 wo, float alpha, vec2 u) {
    // Stretch the view so the distribution becomes the unit hemisphere, sample the projected
    // disk the view sees (a half disk warped by the view's tilt), and unstretch the normal.
    vec3 v = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float len2 = v.x * v.x + v.y * v.y;
    vec3 t1 = len2 > 0.0 ? vec3(-v.y, v.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(v, t1);
    float r = sqrt(u.x);
    float phi = 2.0 * PN_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + v.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
    return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0, nh.z)));
}

// Density of ggxSampleVisibleNormal over microfacet normals (solid angle).
float ggxVisibleNormalPdf(vec3 wo, vec3 h, float alpha) {
    if (wo.z <= 0.0) return 0.0;
    return ggxG1(wo, alpha) * max(0.0, dot(wo, h)) * ggxD(h, alpha) / wo.z;
}

// Microfacet reflection without Fresnel (callers multiply by theirs, taken at dot(wo, h)):
// f = D G2 / (4 cos_o cos_i), both directions above the surface.
float ggxReflectionEval(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    vec3 h = normalize(wo + wi);
    return ggxD(h, alpha) * ggxG2(wo, wi, alpha) / (4.0 * wo.z * wi.z);
}

// Density of ggxReflectionSample: the visible-normal density times the reflection Jacobian.
float ggxReflectionPdf(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    vec3 h = normalize(wo + wi);
    float oh = dot(wo, h);
    return oh > 0.0 ? ggxVisibleNormalPdf(wo, h, alpha) / (4.0 * oh) : 0.0;
}

// wo mirrored about a visible microfacet normal; may point below the surface (then the sample is
// lost: its density is not counted by ggxReflectionPdf, so the estimator stays unbiased).
vec3 ggxReflectionSample(vec3 wo, float alpha, vec2 u) {
    vec3 h = ggxSampleVisibleNormal(wo, alpha, u);
    return reflect(-wo, h);
}

#endif
