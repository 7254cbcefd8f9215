// The kernel specialisation's table (render/kernel_features.h): every bit named once, each in its
// own constant, and the edits it lists are the ones after which its detector must run again.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/tuning.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

TEST(KernelSpecTable, EveryBitHasOneRowAndOneName) {
    std::uint32_t capabilities = 0, options = 0;
    std::set<std::string> names;
    for (const KernelBit& row : kernelBits()) {
        std::uint32_t& seen = row.option ? options : capabilities;
        EXPECT_EQ(seen & row.bit, 0u) << row.name << " shares its bit with another row";
        seen |= row.bit;
        EXPECT_TRUE(names.insert(row.name).second) << row.name;
        // Capabilities come from the scene, so each has a detector and an edit that changes it.
        if (!row.option) {
            EXPECT_TRUE(row.detect && row.changedBy != kEditNone) << row.name;
        }
    }
    EXPECT_EQ(capabilities, PN_FEATURE_ALL);
    EXPECT_EQ(options, PN_OPTION_ONE_TOP_LIGHT | PN_OPTION_CULL_BACKFACES | PN_OPTION_FRAME_STATS);
}

// After an edit of one kind, detecting again only the bits the table says that kind changes gives
// what detecting everything gives; detecting for another kind of edit misses the change.
void expectEditFound(const SceneArrays& before, const SceneArrays& after, std::uint32_t edit, std::uint32_t bit,
                     bool option) {
    const KernelSpec inUse = kernelSpec(before);
    const KernelSpec refreshed = kernelSpecAfter(inUse, after, edit);
    EXPECT_EQ(refreshed, kernelSpec(after));
    EXPECT_NE(refreshed, inUse) << "the edit changed nothing the kernels care about: the test tests nothing";
    const std::uint32_t other = edit == kEditLights ? kEditEnvironment : kEditLights;
    EXPECT_EQ(kernelSpecAfter(inUse, after, other), inUse);
    EXPECT_NE((option ? refreshed.options : refreshed.capabilities) & bit,
              (option ? inUse.options : inUse.capabilities) & bit);
}

TEST(KernelSpecTable, EachEditRedetectsTheBitsItCanChange) {
    const SceneArrays box = buildSceneArrays(makeCornellBox());
    SceneArrays glass = box;
    glass.materials[0].transmission = 1;
    expectEditFound(box, glass, kEditMaterials, PN_FEATURE_TRANSMISSION, false);
    expectEditFound(glass, box, kEditMaterials, PN_FEATURE_TRANSMISSION, false);  // the last glass turned matte
    SceneArrays sprite = box;
    sprite.triVerts[0].flags |= PN_TRI_SPRITE;
    expectEditFound(box, sprite, kEditGeometry, PN_FEATURE_SPRITES, false);
    SceneArrays manyLights = box;
    manyLights.lightRefs.resize(kShadowRouletteMinLights);
    expectEditFound(box, manyLights, kEditLights, PN_FEATURE_SHADOW_ROULETTE, false);
    SceneArrays sky = box;
    sky.env.width = sky.env.height = 1;
    expectEditFound(box, sky, kEditEnvironment, PN_FEATURE_ENV_MAP, false);
    SceneArrays oneLight = box;
    oneLight.topLightCount = box.topLightCount == 1 ? 2 : 1;
    expectEditFound(box, oneLight, kEditLights, PN_OPTION_ONE_TOP_LIGHT, true);
}

TEST(KernelSpecTable, ModesComeFromSettingsAndTheGenericKernelPromisesNothing) {
    const SceneArrays box = buildSceneArrays(makeCornellBox());
    const KernelSpec plain = kernelSpec(box);
    EXPECT_FALSE(plain.has(PN_FEATURE_GLOSSY) || plain.has(PN_FEATURE_TEXTURES) || plain.has(PN_FEATURE_SPHERES));
    EXPECT_EQ(plain.options & (PN_OPTION_CULL_BACKFACES | PN_OPTION_FRAME_STATS), 0u);
    const KernelSpec both = kernelSpec(box, true, true);
    EXPECT_EQ(both.capabilities, plain.capabilities);
    EXPECT_TRUE(both.hasOption(PN_OPTION_CULL_BACKFACES) && both.hasOption(PN_OPTION_FRAME_STATS));

    const RenderTuning saved = renderTuning();
    RenderTuning generic = saved;
    generic.genericKernel = true;
    setRenderTuning(generic);
    const KernelSpec all = kernelSpec(box, true);
    setRenderTuning(saved);
    EXPECT_EQ(all.capabilities, PN_FEATURE_ALL);
    EXPECT_EQ(all.options, PN_OPTION_CULL_BACKFACES);  // a mode asked for, but no promise
    EXPECT_EQ(kernelSpecNames(all), "all+cull-backfaces");
    EXPECT_EQ(kernelSpecNames(KernelSpec{PN_FEATURE_SPHERES | PN_FEATURE_GLOSSY, PN_OPTION_NONE}), "spheres,glossy");
    EXPECT_EQ(kernelSpecNames(KernelSpec{0, PN_OPTION_ONE_TOP_LIGHT}), "none+one-top-light");
}

}  // namespace
}  // namespace penumbra
