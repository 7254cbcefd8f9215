#include "render/kernel_features.h"

#include <algorithm>

#include "render/tuning.h"

namespace penumbra {
namespace {

bool anyTriangle(const SceneArrays& a, std::uint32_t flag) {
    return std::any_of(a.triVerts.begin(), a.triVerts.end(), [&](const shader::TriVerts& t) { return (t.flags & flag) != 0; });
}

template <typename Predicate>
bool anyMaterial(const SceneArrays& a, Predicate&& p) {
    return std::any_of(a.materials.begin(), a.materials.end(), p);
}

bool hasTextures(const SceneArrays& a) {
    // Sprites are always textured (their alpha cuts them out).
    return anyTriangle(a, PN_TRI_SPRITE) || anyMaterial(a, [](const shader::Material& m) {
               return m.albedoTexture != PN_NO_TEXTURE || m.metallicRoughnessTexture != PN_NO_TEXTURE ||
                      m.emissionTexture != PN_NO_TEXTURE;
           });
}

constexpr std::uint32_t kGeometryOrMaterials = kEditGeometry | kEditMaterials;

const KernelBit kBits[] = {
    {PN_FEATURE_SPHERES, false, "spheres", [](const SceneArrays& a) { return a.sphereCount > 0; }, kEditGeometry},
    {PN_FEATURE_ALPHA_TEST, false, "alpha-test", [](const SceneArrays& a) { return anyTriangle(a, PN_TRI_ALPHA_TESTED); },
     kEditGeometry},
    {PN_FEATURE_TEXTURES, false, "textures", hasTextures, kGeometryOrMaterials},
    {PN_FEATURE_NORMAL_MAPS, false, "normal-maps",
     [](const SceneArrays& a) { return anyMaterial(a, [](const shader::Material& m) { return m.normalTexture != PN_NO_TEXTURE; }); },
     kEditMaterials},
    {PN_FEATURE_ABSORPTION, false, "absorption",
     [](const SceneArrays& a) {
         return anyMaterial(a, [](const shader::Material& m) { return m.absorption.x > 0 || m.absorption.y > 0 || m.absorption.z > 0; });
     },
     kEditMaterials},
    {PN_FEATURE_TRANSMISSION, false, "transmission",
     [](const SceneArrays& a) { return anyMaterial(a, [](const shader::Material& m) { return m.transmission > 0; }); },
     kEditMaterials},
    {PN_FEATURE_ENV_MAP, false, "environment-map", [](const SceneArrays& a) { return a.env.width > 0; }, kEditEnvironment},
    {PN_FEATURE_SPRITES, false, "sprites", [](const SceneArrays& a) { return anyTriangle(a, PN_TRI_SPRITE); }, kEditGeometry},
    {PN_FEATURE_SKY_PORTALS, false, "sky-portals",
     [](const SceneArrays& a) {
         return anyMaterial(a, [](const shader::Material& m) { return (m.flags & PN_MATERIAL_SKY_PORTAL) != 0; });
     },
     kEditMaterials},
    {PN_FEATURE_INSTANCES, false, "instances", [](const SceneArrays& a) { return !a.instances.empty(); }, kEditGeometry},
    {PN_FEATURE_LIGHT_GRID, false, "light-grid", [](const SceneArrays& a) { return !a.lightGrid.empty(); }, kEditLights},
    {PN_FEATURE_SHADOW_ROULETTE, false, "shadow-roulette",
     [](const SceneArrays& a) { return a.lightRefs.size() >= kShadowRouletteMinLights; }, kEditLights},
    {PN_FEATURE_GLOSSY, false, "glossy",
     [](const SceneArrays& a) { return anyMaterial(a, [](const shader::Material& m) { return m.metallic > 0 || m.specular > 0; }); },
     kEditMaterials},
    {PN_OPTION_ONE_TOP_LIGHT, true, "one-top-light", [](const SceneArrays& a) { return a.topLightCount == 1; }, kEditLights},
    {PN_OPTION_CULL_BACKFACES, true, "cull-backfaces", nullptr, kEditNone},  // --cull-backfaces
    {PN_OPTION_FRAME_STATS, true, "frame-stats", nullptr, kEditNone},        // the panel's or bench's counting
};

// Sets or clears `row`'s bit in `spec` by its detector (rows without one are left as they are).
void detect(KernelSpec& spec, const KernelBit& row, const SceneArrays& arrays) {
    if (!row.detect) return;
    std::uint32_t& word = row.option ? spec.options : spec.capabilities;
    word = row.detect(arrays) ? word | row.bit : word & ~row.bit;
}

}  // namespace

std::span<const KernelBit> kernelBits() { return kBits; }

KernelSpec kernelSpec(const SceneArrays& arrays, bool cullBackfaces, bool frameStatistics) {
    KernelSpec spec{0u, PN_OPTION_NONE};
    if (renderTuning().genericKernel) spec.capabilities = PN_FEATURE_ALL;  // and no promise
    else
        for (const KernelBit& row : kBits) detect(spec, row, arrays);
    return spec.withOption(PN_OPTION_CULL_BACKFACES, cullBackfaces).withOption(PN_OPTION_FRAME_STATS, frameStatistics);
}

KernelSpec kernelSpecAfter(KernelSpec inUse, const SceneArrays& arrays, std::uint32_t edits) {
    if (renderTuning().genericKernel) return inUse;
    for (const KernelBit& row : kBits)
        if (row.changedBy & edits) detect(inUse, row, arrays);
    return inUse;
}

std::string kernelSpecNames(KernelSpec spec) {
    std::string out;
    auto append = [&](const char* name, char separator) {
        if (!out.empty()) out += separator;  // appended, not `"," + name`: GCC 12 -Wrestrict misfires on that
        out += name;
    };
    if (spec.capabilities == PN_FEATURE_ALL) append("all", ',');
    else
        for (const KernelBit& row : kBits)
            if (!row.option && (spec.capabilities & row.bit)) append(row.name, ',');
    if (out.empty()) out = "none";
    char separator = '+';
    for (const KernelBit& row : kBits)
        if (row.option && (spec.options & row.bit)) {
            append(row.name, separator);
            separator = ',';
        }
    return out;
}

}  // namespace penumbra
