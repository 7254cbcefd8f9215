// What a playing level shows of its state (scene/doom/level_looks.h): a switch's wall turns to
// its other texture when used and back after Doom's button time when it is repeatable; a key's
// sprite vanishes when the key is picked up. On the small map (doom_test_map.h) with hand-made
// materials, and on Freedoom's E1M1 as the WAD loader builds it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "../wad/freedoom_wad.h"
#include "doom_test_map.h"
#include "scene/doom/level.h"
#include "scene/doom/level_looks.h"
#include "scene/io/wad/units.h"
#include "scene/io/wad/wad_loader.h"

namespace penumbra::doom {
namespace {

bool contains(const std::vector<std::uint32_t>& list, std::uint32_t value) {
    return std::find(list.begin(), list.end(), value) != list.end();
}

const std::string& albedoName(const Scene& scene, std::uint32_t material) {
    return scene.textures.at(std::size_t(scene.materials.at(material).albedoTexture.texture)).name;
}

TEST(DoomLooks, OtherSwitchTexturePairsSw1AndSw2) {
    EXPECT_EQ(otherSwitchTexture("SW1EXIT"), "SW2EXIT");
    EXPECT_EQ(otherSwitchTexture("SW2STRTN"), "SW1STRTN");
    EXPECT_EQ(otherSwitchTexture("STARTAN3"), "");
    EXPECT_EQ(otherSwitchTexture("SW3X"), "");
    EXPECT_TRUE(turnsSwitch(62));   // SR lift
    EXPECT_TRUE(turnsSwitch(103));  // S1 door
    EXPECT_FALSE(turnsSwitch(1));   // DR: a door, no switch
    EXPECT_FALSE(turnsSwitch(88));  // WR lift
}

// The repeatable lift switch (SR 62): textures 10 (as drawn) and 11 (the other), glow 20 and 21.
TEST(DoomLooks, RepeatableSwitchTurnsAndTurnsBackAfterButtonTime) {
    const test::TestLevelMap t = test::doomTestMap();
    Level level(t.map);
    std::vector<Material> materials(2);
    materials[1].albedoTexture.texture = 10;
    materials[1].emissionTexture.texture = 20;
    level.switchMaterials().push_back({t.liftSwitch, 1, {10, 11}, {20, 21}});
    EXPECT_TRUE(applyLooks(level, materials).empty());
    ASSERT_TRUE(level.trigger(t.liftSwitch));
    EXPECT_EQ(applyLooks(level, materials), std::vector<std::uint32_t>{1});
    EXPECT_EQ(materials[1].albedoTexture.texture, 11);
    EXPECT_EQ(materials[1].emissionTexture.texture, 21);
    EXPECT_TRUE(applyLooks(level, materials).empty());  // nothing new: nothing to send up
    for (int i = 0; i + 1 < kButtonTics; ++i) level.tic(std::nullopt);
    EXPECT_TRUE(applyLooks(level, materials).empty());
    EXPECT_EQ(materials[1].albedoTexture.texture, 11);
    level.tic(std::nullopt);  // 35 tics: Doom's BUTTONTIME
    EXPECT_EQ(applyLooks(level, materials), std::vector<std::uint32_t>{1});
    EXPECT_EQ(materials[1].albedoTexture.texture, 10);
    EXPECT_EQ(materials[1].emissionTexture.texture, 20);
    EXPECT_EQ(materials[0].albedoTexture.texture, -1);  // other materials untouched
}

TEST(DoomLooks, OneShotSwitchStaysTurned) {
    const test::TestLevelMap t = test::doomTestMap();
    Level level(t.map);
    std::vector<Material> materials(1);
    materials[0].albedoTexture.texture = 3;
    level.switchMaterials().push_back({t.switchA, 0, {3, 4}, {-1, -1}});
    ASSERT_TRUE(level.trigger(t.switchA));
    EXPECT_EQ(applyLooks(level, materials), std::vector<std::uint32_t>{0});
    for (int i = 0; i < 4 * kButtonTics; ++i) level.tic(std::nullopt);
    EXPECT_TRUE(applyLooks(level, materials).empty());
    EXPECT_EQ(materials[0].albedoTexture.texture, 4);
    EXPECT_FALSE(materials[0].emissionTexture.present());  // no glow was made up
}

TEST(DoomLooks, PickedUpKeyVanishes) {
    const test::TestLevelMap t = test::doomTestMap();
    Level level(t.map);
    std::vector<Material> materials(1);
    materials[0].alphaCutoff = 0.5f;
    level.keyMaterials().push_back({1, 0, 0.5f});  // thing 1: the blue card in room B
    EXPECT_TRUE(applyLooks(level, materials).empty());
    level.touchThings({100, 128, 0});  // far from it
    EXPECT_TRUE(applyLooks(level, materials).empty());
    level.touchThings({400, 200, 0});
    ASSERT_TRUE(level.hasKey(Key::Blue));
    EXPECT_EQ(applyLooks(level, materials), std::vector<std::uint32_t>{0});
    EXPECT_GT(materials[0].alphaCutoff, 1.0f);  // no texel passes: nothing drawn
}

// Freedoom's E1M1 as loaded: each switch wall has a material of its own, drawn with an SW1 or
// SW2 texture, and using the switch turns that material (and no other) to the other texture.
TEST(DoomLooks, FreedoomSwitchWallsTurnTheirOwnMaterial) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    Scene scene = loadWadFromMemory(bytes, "E1M1", "freedoom1.wad");
    ASSERT_TRUE(scene.doomLevel);
    Level level = *scene.doomLevel;
    ASSERT_FALSE(level.switchMaterials().empty());
    std::set<std::uint32_t> own;
    for (const SwitchMaterial& s : level.switchMaterials()) {
        EXPECT_TRUE(own.insert(s.material).second) << "a switch material is shared";
        const std::string& drawn = albedoName(scene, s.material);
        EXPECT_EQ(drawn.substr(0, 2), "SW") << drawn;
        EXPECT_EQ(scene.textures.at(std::size_t(s.albedo[1])).name, otherSwitchTexture(drawn));
        EXPECT_TRUE(turnsSwitch(level.lines().at(s.line).special));
    }
    const SwitchMaterial s = level.switchMaterials().front();
    const std::string drawn = albedoName(scene, s.material);
    level.trigger(s.line);  // whether or not it moved something
    if (!level.switchFlipped(s.line)) GTEST_SKIP() << "the first switch of E1M1 does nothing when fired alone";
    const std::vector<Material> before = scene.materials;
    const std::vector<std::uint32_t> changed = applyLooks(level, scene.materials);
    EXPECT_TRUE(contains(changed, s.material));
    EXPECT_EQ(albedoName(scene, s.material), otherSwitchTexture(drawn));
    for (std::uint32_t m = 0; m < scene.materials.size(); ++m) {
        if (contains(changed, m)) continue;
        EXPECT_EQ(scene.materials[m].albedoTexture.texture, before[m].albedoTexture.texture) << m;
    }
}

// Freedoom's E1M1 as loaded: each key's sprite has a material of its own, which hides when the
// key is picked up; the other sprites keep theirs.
TEST(DoomLooks, FreedoomKeySpriteVanishesWhenPickedUp) {
    REQUIRE_WAD(bytes, "freedoom1.wad");
    Scene scene = loadWadFromMemory(bytes, "E1M1", "freedoom1.wad");
    Level level = *scene.doomLevel;
    ASSERT_FALSE(level.keyMaterials().empty());
    ASSERT_FALSE(level.keyPositions().empty());
    // Named, not a structured binding: clang 14 (the sanitizer job) cannot capture those.
    const auto key = level.keyPositions().front();
    // The key's sprite: the one standing there, with a material no other sprite uses.
    const auto at = [&](const Sprite& s) {
        const Vec3 p = wad::sceneToMap(s.position);
        return std::abs(p.x - key.first) < 0.5 && std::abs(p.y - key.second) < 0.5;
    };
    const auto sprite = std::find_if(scene.sprites.begin(), scene.sprites.end(), at);
    ASSERT_NE(sprite, scene.sprites.end());
    const std::uint32_t keyMaterial = sprite->material;
    EXPECT_EQ(std::count_if(scene.sprites.begin(), scene.sprites.end(),
                            [&](const Sprite& s) { return s.material == keyMaterial; }),
              1);
    EXPECT_LT(scene.materials[keyMaterial].alphaCutoff, 1.0f);  // drawn before it is taken
    level.touchThings({key.first, key.second, 0});
    const std::vector<std::uint32_t> changed = applyLooks(level, scene.materials);
    EXPECT_EQ(changed, std::vector<std::uint32_t>{keyMaterial});
    EXPECT_GT(scene.materials[keyMaterial].alphaCutoff, 1.0f);
    EXPECT_EQ(level.keyPositions().size() + 1, level.keyMaterials().size());
}

}  // namespace
}  // namespace penumbra::doom
