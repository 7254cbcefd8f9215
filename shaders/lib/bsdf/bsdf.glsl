// The one BSDF every surface uses: a mixture of lobes set by the material's parameters
// (docs/MATERIALS.md), evaluated and sampled in the local shading frame, where z is the shading
// normal on wo's side (so wo.z > 0; wi.z < 0 means transmission).
//
//   f = metallic                           * conductor (GGX or mirror, Schlick Fresnel from base colour)
//     + (1 - metallic) * transmission      * dielectric (rough or smooth glass, tinted on refraction)
//     + (1 - metallic) * (1 - transmission) * (coat: specular * dielectric Fresnel * GGX or mirror
//                                             + base colour / pi * (1 - Fc(wo)) (1 - Fc(wi)))
//
// Sampling picks one lobe with a probability that depends only on the parameters and wo, so the
// density of the whole mixture is known and every sample's weight is f cos / pdf of the mixture
// (delta lobes, which eval and pdf never see, carry their own weight).
#ifndef PN_BSDF_GLSL
#define PN_BSDF_GLSL

#include "lib/bsdf/dielectric.glsl"
#include "lib/bsdf/fresnel.glsl"
#include "lib/bsdf/ggx.glsl"
#include "lib/bsdf/lambert.glsl"

struct BsdfParams {
    vec3 baseColor;      // [0, 1]
    float metallic;      // [0, 1]
    float roughness;     // perceptual, [0, 1]; below PN_SMOOTH_ROUGHNESS the specular lobes are deltas
    float ior;           // >= 1
    float transmission;  // [0, 1]
    float specular;      // [0, 1] coat strength
    bool entering;       // wo is outside the material (refraction goes from air into it)
    // Known to be its diffuse lobe alone (metallic, specular and transmission 0, as in a kernel
    // made for a scene without metal, coats or glass: lib/material.glsl): eval, pdf and sample
    // then give exactly what the mixture's code would, its other terms being zero, without its
    // Fresnel and GGX arithmetic. Set only where the compiler knows it, so that kernels of scenes
    // with glossy materials carry no extra branch.
    bool lambertian;
};

struct BsdfSample {
    vec3 wi;       // local frame
    vec3 weight;   // f |cos| / pdf; zero when the sample is lost
    float pdf;     // solid-angle density of the mixture (or, for a delta lobe, its probability)
    bool isDelta;  // from a perfectly smooth lobe: no MIS with light sampling
};

float bsdfAlpha(BsdfParams p) { return p.roughness * p.roughness; }
bool bsdfIsSmooth(BsdfParams p) { return p.roughness < PN_SMOOTH_ROUGHNESS; }
float bsdfEta(BsdfParams p) { return p.entering ? p.ior : 1.0 / p.ior; }

// The coat's Fresnel reflectance at cosTheta (the coat is seen from outside whichever face was hit).
float coatFresnel(BsdfParams p, float cosTheta) { return p.specular * fresnelDielectric(cosTheta, p.ior); }

// Lobe selection probabilities for wo: conductor, dielectric, coat specular, diffuse (sum 1).
vec4 bsdfLobeProbabilities(BsdfParams p, vec3 wo) {
    float conductor = p.metallic;
    float glass = (1.0 - p.metallic) * p.transmission;
    float plastic = (1.0 - p.metallic) * (1.0 - p.transmission);
    float fc = coatFresnel(p, wo.z);
    float diffuseShare = (1.0 - fc) * max(dot(p.baseColor, vec3(1.0 / 3.0)), 0.05);
    float coatShare = fc > 0.0 ? fc / (fc + diffuseShare) : 0.0;
    return vec4(conductor, glass, plastic * coatShare, plastic * (1.0 - coatShare));
}

// f(wo, wi) of the non-delta lobes.
vec3 bsdfEval(BsdfParams p, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0) return vec3(0.0);
    if (p.lambertian) return wi.z > 0.0 ? lambertEval(p.baseColor) : vec3(0.0);
    float alpha = bsdfAlpha(p);
    bool isSmooth = bsdfIsSmooth(p);
    float plastic = (1.0 - p.metallic) * (1.0 - p.transmission);
    vec3 f = vec3(0.0);
    if (wi.z > 0.0) {
        f += plastic * lambertEval(p.baseColor) * (1.0 - coatFresnel(p, wo.z)) * (1.0 - coatFresnel(p, wi.z));
        if (!isSmooth) {
            float specular = ggxReflectionEval(wo, wi, alpha);
            float oh = dot(wo, normalize(wo + wi));
            f += p.metallic * fresnelSchlick(p.baseColor, oh) * specular;
            f += plastic * coatFresnel(p, oh) * specular;
        }
    }
    float glass = (1.0 - p.metallic) * p.transmission;
    if (glass > 0.0 && !isSmooth) {
        float unused;
        float fd = dielectricEvalRough(wo, wi, bsdfEta(p), alpha, unused);
        f += glass * fd * (wi.z < 0.0 ? p.baseColor : vec3(1.0));
    }
    return f;
}

// Density with which bsdfSample returns wi from a non-delta lobe.
float bsdfPdf(BsdfParams p, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0) return 0.0;
    if (p.lambertian) return lambertPdfLocal(wi);
    vec4 prob = bsdfLobeProbabilities(p, wo);
    float pdf = prob.w * lambertPdfLocal(wi);
    if (bsdfIsSmooth(p)) return pdf;
    float alpha = bsdfAlpha(p);
    pdf += (prob.x + prob.z) * ggxReflectionPdf(wo, wi, alpha);
    if (prob.y > 0.0) {
        float glassPdf;
        dielectricEvalRough(wo, wi, bsdfEta(p), alpha, glassPdf);
        pdf += prob.y * glassPdf;
    }
    return pdf;
}

BsdfSample bsdfLost() { return BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false); }

// Weight of a non-delta sample: the whole mixture's f cos / pdf at wi.
BsdfSample bsdfFinishSample(BsdfParams p, vec3 wo, vec3 wi) {
    if (wi == vec3(0.0)) return bsdfLost();
    float pdf = bsdfPdf(p, wo, wi);
    if (!(pdf > 0.0)) return bsdfLost();
    return BsdfSample(wi, bsdfEval(p, wo, wi) * abs(wi.z) / pdf, pdf, false);
}

BsdfSample bsdfSample(BsdfParams p, vec3 wo, vec3 u) {
    if (wo.z <= 0.0) return bsdfLost();
    if (p.lambertian) return bsdfFinishSample(p, wo, lambertSampleLocal(u.yz));
    vec4 prob = bsdfLobeProbabilities(p, wo);
    bool isSmooth = bsdfIsSmooth(p);
    float alpha = bsdfAlpha(p);
    vec3 mirror = vec3(-wo.x, -wo.y, wo.z);
    // Pick a lobe with u.x, then reuse the remainder of u.x's interval as a fresh number.
    float x = u.x;
    if (x < prob.x) {  // conductor
        if (isSmooth) return BsdfSample(mirror, fresnelSchlick(p.baseColor, wo.z), prob.x, true);
        return bsdfFinishSample(p, wo, ggxReflectionSample(wo, alpha, u.yz));
    }
    x -= prob.x;
    if (x < prob.y) {  // dielectric
        float reuse = x / prob.y;
        float eta = bsdfEta(p);
        if (isSmooth) {
            float choice;
            vec3 wi = dielectricSampleSmooth(wo, eta, reuse, choice);
            return BsdfSample(wi, wi.z < 0.0 ? p.baseColor : vec3(1.0), prob.y * choice, true);
        }
        return bsdfFinishSample(p, wo, dielectricSampleRough(wo, eta, alpha, vec3(u.yz, reuse)));
    }
    x -= prob.y;
    if (x < prob.z) {  // coat
        if (isSmooth) {
            float plastic = (1.0 - p.metallic) * (1.0 - p.transmission);
            return BsdfSample(mirror, vec3(plastic * coatFresnel(p, wo.z) / prob.z), prob.z, true);
        }
        return bsdfFinishSample(p, wo, ggxReflectionSample(wo, alpha, u.yz));
    }
    if (prob.w <= 0.0) return bsdfLost();
    return bsdfFinishSample(p, wo, lambertSampleLocal(u.yz));
}

#endif
