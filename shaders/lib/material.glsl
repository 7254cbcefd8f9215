// From a GPU Material and a texture coordinate to what shading needs: BSDF parameters (base
// colour and metallic-roughness textures applied, glTF conventions) and emitted radiance.
#ifndef PN_MATERIAL_GLSL
#define PN_MATERIAL_GLSL

#include "lib/bsdf/bsdf.glsl"
#include "lib/textures.glsl"

// frontFace: the ray hit the side the winding calls front (outside, for a closed transmissive
// mesh). One-sided opaque materials reflect nothing from the back.
BsdfParams materialBsdf(Material m, vec2 uv, bool frontFace) {
    BsdfParams p;
    p.baseColor = materialBaseColor(m, uv).rgb;
    p.metallic = m.metallic;
    p.roughness = m.roughness;
    if (PN_HAS(PN_FEATURE_TEXTURES) && m.metallicRoughnessTexture != PN_NO_TEXTURE) {
        vec4 mr = sampleTexture(m.metallicRoughnessTexture, uv, m.metallicRoughnessWrap);
        p.roughness *= mr.g;
        p.metallic *= mr.b;
    }
    p.metallic = PN_HAS(PN_FEATURE_GLOSSY) ? clamp(p.metallic, 0.0, 1.0) : 0.0;
    p.roughness = clamp(p.roughness, 0.0, 1.0);
    p.ior = max(m.ior, 1.0);
    p.transmission = PN_HAS(PN_FEATURE_TRANSMISSION) ? clamp(m.transmission, 0.0, 1.0) : 0.0;
    p.specular = PN_HAS(PN_FEATURE_GLOSSY) ? clamp(m.specular, 0.0, 1.0) : 0.0;
    p.entering = frontFace;
    p.lambertian = !PN_HAS(PN_FEATURE_GLOSSY) && !PN_HAS(PN_FEATURE_TRANSMISSION);
    if ((m.flags & PN_MATERIAL_ONE_SIDED) != 0u && !frontFace && p.transmission == 0.0) {
        p.baseColor = vec3(0.0);
        p.metallic = 0.0;
        p.specular = 0.0;
    }
    return p;
}

vec3 materialEmission(Material m, vec2 uv) {
    if (!PN_HAS(PN_FEATURE_TEXTURES) || m.emissionTexture == PN_NO_TEXTURE) return m.emission;
    return m.emission * sampleTexture(m.emissionTexture, uv, m.emissionWrap).rgb;
}

#endif
