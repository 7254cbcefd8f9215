// A dielectric boundary (glass, water): Fresnel-weighted choice between reflection and
// refraction, total internal reflection, smooth (delta) or rough (GGX, Walter et al. 2007 with
// visible-normal sampling). Local frame: z is the normal on wo's side, so wo.z > 0 and refracted
// directions have wi.z < 0. eta = ior of the far side / ior of wo's side.
//
// Radiance is not scaled by 1/eta^2 on refraction: that factor cancels for light that enters
// and leaves an object, and leaving it out keeps every refraction lossless (docs/MATERIALS.md).
#ifndef PN_BSDF_DIELECTRIC_GLSL
#define PN_BSDF_DIELECTRIC_GLSL

#include "lib/bsdf/fresnel.glsl"
#include "lib/bsdf/ggx.glsl"

// The microfacet normal shared by wo and wi (reflection or refraction), facing +z; false when
// the pair is impossible (a microfacet seen from behind).
bool dielectricHalfVector(vec3 wo, vec3 wi, float eta, out vec3 h, out float etaPair) {
    bool reflection = wi.z > 0.0;
    etaPair = reflection ? 1.0 : eta;
    h = wi * etaPair + wo;
    if (wi.z == 0.0 || dot(h, h) == 0.0) return false;
    h = normalize(h);
    if (h.z < 0.0) h = -h;
    // Both directions must see the front of the microfacet from their own side.
    return dot(h, wi) * wi.z > 0.0 && dot(h, wo) * wo.z > 0.0;
}

// f of the rough dielectric for (wo, wi), and the density of dielectricSampleRough in *pdf.
float dielectricEvalRough(vec3 wo, vec3 wi, float eta, float alpha, out float pdf) {
    pdf = 0.0;
    if (wo.z <= 0.0) return 0.0;
    vec3 h;
    float etaPair;
    if (!dielectricHalfVector(wo, wi, eta, h, etaPair)) return 0.0;
    float oh = dot(wo, h), ih = dot(wi, h);
    float F = fresnelDielectric(oh, eta);
    float visible = ggxVisibleNormalPdf(wo, h, alpha);
    float D = ggxD(h, alpha), G = ggxG2(wo, wi, alpha);
    if (wi.z > 0.0) {
        pdf = visible / (4.0 * oh) * F;
        return F * D * G / (4.0 * wo.z * wi.z);
    }
    float denom = ih + oh / eta;
    denom *= denom;
    pdf = visible * abs(ih) / denom * (1.0 - F);
    return (1.0 - F) * D * G * abs(ih * oh) / (denom * wo.z * abs(wi.z));
}

// A direction from the rough dielectric; wi is (0,0,0) when the sample is lost.
vec3 dielectricSampleRough(vec3 wo, float eta, float alpha, vec3 u) {
    vec3 h = ggxSampleVisibleNormal(wo, alpha, u.xy);
    float oh = dot(wo, h);
    if (oh <= 0.0) return vec3(0.0);
    float F = fresnelDielectric(oh, eta);
    if (u.z < F) {
        vec3 wi = reflect(-wo, h);
        return wi.z > 0.0 ? wi : vec3(0.0);
    }
    vec3 wi;
    if (!refractDirection(wo, h, eta, wi) || wi.z >= 0.0) return vec3(0.0);
    return wi;
}

// The smooth dielectric's two delta directions: reflection with probability F, else refraction.
// *probability is that choice's probability (it equals the lobe's weight, so f cos / pdf = 1).
vec3 dielectricSampleSmooth(vec3 wo, float eta, float u, out float probability) {
    float F = fresnelDielectric(wo.z, eta);
    vec3 wt;
    if (u < F || !refractDirection(wo, vec3(0.0, 0.0, 1.0), eta, wt)) {
        probability = F;
        return vec3(-wo.x, -wo.y, wo.z);
    }
    probability = 1.0 - F;
    return wt;
}

#endif
