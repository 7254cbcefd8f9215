#include "render/kernel_features.h"

#include "render/tuning.h"

namespace penumbra {

std::uint32_t kernelFeatures(const SceneArrays& a, Accel accel, bool cullBackfaces) {
    const std::uint32_t cull = cullBackfaces ? PN_FEATURE_CULL_BACKFACES : 0u;
    if (renderTuning().genericKernel) return PN_FEATURE_ALL | cull;
    std::uint32_t f = cull;
    if (a.sphereCount > 0) f |= PN_FEATURE_SPHERES;
    for (const shader::TriVerts& t : a.triVerts) {
        if (t.flags & PN_TRI_ALPHA_TESTED) f |= PN_FEATURE_ALPHA_TEST;
        if (t.flags & PN_TRI_SPRITE) f |= PN_FEATURE_SPRITES | PN_FEATURE_TEXTURES;
    }
    for (const shader::Material& m : a.materials) {
        if (m.albedoTexture != PN_NO_TEXTURE || m.metallicRoughnessTexture != PN_NO_TEXTURE ||
            m.emissionTexture != PN_NO_TEXTURE)
            f |= PN_FEATURE_TEXTURES;
        if (m.normalTexture != PN_NO_TEXTURE) f |= PN_FEATURE_NORMAL_MAPS;
        if (m.absorption.x > 0 || m.absorption.y > 0 || m.absorption.z > 0) f |= PN_FEATURE_ABSORPTION;
        if (m.transmission > 0) f |= PN_FEATURE_TRANSMISSION;
        if (m.metallic > 0 || m.specular > 0) f |= PN_FEATURE_GLOSSY;
        if (m.flags & PN_MATERIAL_SKY_PORTAL) f |= PN_FEATURE_SKY_PORTALS;
    }
    if (a.env.width > 0) f |= PN_FEATURE_ENV_MAP;
    if (accel == Accel::Brute) f |= PN_FEATURE_BRUTE_FORCE;
    if (!a.instances.empty()) f |= PN_FEATURE_INSTANCES;
    if (accel == Accel::Wide && !a.wideNodes.empty()) f |= PN_FEATURE_WIDE_BVH;
    if (!a.lightGrid.empty()) f |= PN_FEATURE_LIGHT_GRID;
    if (a.topLightCount == 1) f |= PN_FEATURE_ONE_TOP_LIGHT;
    if (a.lightRefs.size() >= kShadowRouletteMinLights) f |= PN_FEATURE_SHADOW_ROULETTE;
    return f;
}

std::string kernelFeatureNames(std::uint32_t features) {
    if (features == PN_FEATURE_ALL) return "all";
    static const std::pair<std::uint32_t, const char*> kNames[] = {
        {PN_FEATURE_SPHERES, "spheres"},         {PN_FEATURE_ALPHA_TEST, "alpha-test"},
        {PN_FEATURE_TEXTURES, "textures"},       {PN_FEATURE_NORMAL_MAPS, "normal-maps"},
        {PN_FEATURE_ABSORPTION, "absorption"},   {PN_FEATURE_TRANSMISSION, "transmission"},
        {PN_FEATURE_ENV_MAP, "environment-map"}, {PN_FEATURE_BRUTE_FORCE, "brute-force"},
        {PN_FEATURE_SPRITES, "sprites"},         {PN_FEATURE_SKY_PORTALS, "sky-portals"},
        {PN_FEATURE_INSTANCES, "instances"},     {PN_FEATURE_WIDE_BVH, "wide-bvh"},
        {PN_FEATURE_LIGHT_GRID, "light-grid"},   {PN_FEATURE_ONE_TOP_LIGHT, "one-top-light"},
        {PN_FEATURE_SHADOW_ROULETTE, "shadow-roulette"}, {PN_FEATURE_GLOSSY, "glossy"},
        {PN_FEATURE_CULL_BACKFACES, "cull-backfaces"}, {PN_FEATURE_FRAME_STATS, "frame-stats"}};
    std::string out;
    for (auto [bit, name] : kNames) {
        if (!(features & bit)) continue;
        if (!out.empty()) out += ',';  // appended, not `"," + name`: GCC 12 -Wrestrict misfires on that
        out += name;
    }
    return out.empty() ? "none" : out;
}

}  // namespace penumbra
