// Materials and textures as the shaders read them.
// Valid GLSL and C++ (see types.h); each struct's size and offsets are checked beside it.
#ifndef PENUMBRA_SHADER_MATERIALS_H
#define PENUMBRA_SHADER_MATERIALS_H

#include "shared/prelude.h"

#ifdef __cplusplus
namespace penumbra::shader {
#endif

// ---- material flags ----
#define PN_MATERIAL_EMISSIVE 1u
#define PN_MATERIAL_ALPHA_TESTED 2u  // texels with alpha below alphaCutoff are holes
#define PN_MATERIAL_ONE_SIDED 4u     // the back face reflects nothing (glTF doubleSided = false)
// Shows the environment seen through it plus its emission (a Doom sky ceiling and its fill light).
#define PN_MATERIAL_SKY_PORTAL 8u
#define PN_MATERIAL_HIDDEN_EMISSION 16u  // camera rays do not see `emission` (Doom's sector light)

// Perceptual roughness below this is shaded as perfectly smooth (delta lobes); at or above it the
// GGX lobes use alpha = roughness^2 (so alpha >= PN_SMOOTH_ROUGHNESS^2, which keeps D finite).
#define PN_SMOOTH_ROUGHNESS 0.02

// ---- texture flags and sampler words (a material's *Wrap fields: PN_WRAP_* for u,
// | PN_WRAP_* for v << 8, | PN_SAMPLER_NEAREST) ----
#define PN_TEXTURE_SRGB 1u
#define PN_WRAP_REPEAT 0u
#define PN_WRAP_CLAMP 1u
#define PN_WRAP_MIRROR 2u
#define PN_SAMPLER_NEAREST 0x10000u  // the nearest texel instead of bilinear filtering
#define PN_NO_TEXTURE 0xffffffffu

// One principled material (see docs/MATERIALS.md), 96 bytes. Lobes: a Lambertian base under a
// dielectric GGX coat (weight `specular`), a GGX conductor (weight `metallic`) and a dielectric
// that refracts (weight (1 - metallic) * transmission). roughness below PN_SMOOTH_ROUGHNESS makes
// the specular lobes perfectly smooth (delta) ones.
PN_STRUCT(Material) {
    vec3 albedo;          // base colour, each channel in [0, 1]; multiplies the texture
    uint flags;           // PN_MATERIAL_*
    vec3 emission;        // emitted radiance from the front face (winding order), W/(m^2 sr) per channel
    float alphaCutoff;    // with PN_MATERIAL_ALPHA_TESTED
    vec3 absorption;      // Beer-Lambert coefficient inside a transmissive material, per metre (0: clear)
    float ior;            // index of refraction, >= 1
    float metallic;       // [0, 1]; multiplies the texture's B channel
    float roughness;      // perceptual, [0, 1]; multiplies the texture's G channel; GGX alpha = roughness^2
    float transmission;   // [0, 1]
    float specular;       // [0, 1]: strength of the dielectric coat over the diffuse base (0: pure Lambert)
    uint albedoTexture;   // PN_NO_TEXTURE or an index into the texture table
    uint albedoWrap;      // sampler word: PN_WRAP_* for u | (PN_WRAP_* for v) << 8 | PN_SAMPLER_NEAREST
    uint metallicRoughnessTexture;  // linear; G = roughness, B = metallic (glTF)
    uint metallicRoughnessWrap;
    uint normalTexture;   // tangent-space normal map, linear
    uint normalWrap;
    uint emissionTexture; // sRGB, multiplies emission
    uint emissionWrap;
};
#ifdef __cplusplus
static_assert(sizeof(Material) == 96 && offsetof(Material, flags) == 12 &&
              offsetof(Material, emission) == 16 && offsetof(Material, alphaCutoff) == 28 &&
              offsetof(Material, absorption) == 32 && offsetof(Material, ior) == 44 &&
              offsetof(Material, metallic) == 48 && offsetof(Material, roughness) == 52 &&
              offsetof(Material, transmission) == 56 && offsetof(Material, specular) == 60 &&
              offsetof(Material, albedoTexture) == 64 && offsetof(Material, albedoWrap) == 68 &&
              offsetof(Material, metallicRoughnessTexture) == 72 && offsetof(Material, normalTexture) == 80 &&
              offsetof(Material, emissionTexture) == 88 && offsetof(Material, emissionWrap) == 92);
#endif

// Where one texture's texels are in the texel buffer, and its animation, 32 bytes. A texture of
// frameCount > 1 is frame `frame` of a cycle whose frames are the textures [index - frame,
// index - frame + frameCount); a lookup of it shows frame (floor(time / secondsPerFrame) + frame)
// mod frameCount of that cycle.
PN_STRUCT(TextureInfo) {
    uint firstTexel;
    uint width;
    uint height;
    uint flags;  // PN_TEXTURE_*
    uint frameCount;
    uint frame;
    float secondsPerFrame;
    uint pad0;
};
#ifdef __cplusplus
static_assert(sizeof(TextureInfo) == 32 && offsetof(TextureInfo, flags) == 12 && offsetof(TextureInfo, frameCount) == 16 &&
              offsetof(TextureInfo, frame) == 20 && offsetof(TextureInfo, secondsPerFrame) == 24);
#endif

#ifdef __cplusplus
}  // namespace penumbra::shader
#endif
#endif
