// The Doom look on the CPU: the glow table and its per-texel weights, sector light, the sky map,
// animation cycles and sprite views, on small WADs written here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/environment.h"
#include "scene/io/wad/animation.h"
#include "scene/io/wad/glow.h"
#include "scene/io/wad/sector_light.h"
#include "scene/io/wad/sky.h"
#include "scene/io/wad/things.h"
#include "scene/io/wad/wad_loader.h"
#include "shared/animation.h"
#include "shared/color.h"
#include "wad_builder.h"
#include "shared/constants.h"

namespace penumbra {
namespace {
using testing::Graphics;
using testing::MapBuilder;
using testing::WadBuilder;
using wad::GlowKind;

TEST(WadGlow, TableNamesWhatGlowsAndHow) {
    EXPECT_EQ(wad::glowOf("NUKAGE2", true).kind, GlowKind::Whole);
    EXPECT_EQ(wad::glowOf("NUKAGE2", false).kind, GlowKind::None)
        << "flat names do not make textures glow";
    EXPECT_EQ(wad::glowOf("LITE3", false).kind, GlowKind::Bright);
    EXPECT_EQ(wad::glowOf("LITEBLU4", false).kind, GlowKind::Bright);
    EXPECT_EQ(wad::glowOf("LITEYEL2", false).kind, GlowKind::Panel)
        << "Freedoom's panels come before LITE*";
    EXPECT_EQ(wad::glowOf("AQLITE18", false).kind, GlowKind::Panel);
    EXPECT_EQ(wad::glowOf("AQF066", true).kind, GlowKind::Panel);
    EXPECT_EQ(wad::glowOf("AQF067", true).kind, GlowKind::None);
    EXPECT_EQ(wad::glowOf("TLITE6_5", true).kind, GlowKind::Bright);
    EXPECT_EQ(wad::glowOf("SW2EXIT", false).kind, GlowKind::Bright);
    EXPECT_EQ(wad::glowOf("COMPUTE2", false).kind, GlowKind::Screen);
    EXPECT_EQ(wad::glowOf("FIREBLU1", false).kind, GlowKind::Whole);
    EXPECT_EQ(wad::glowOf("STARTAN3", false).kind, GlowKind::None);
    EXPECT_EQ(wad::glowOf("SLIME13", true).kind, GlowKind::None)
        << "only the animated SLIME01-12 are liquids";
    EXPECT_GT(wad::glowOf("SLIME09", true).strength, wad::glowOf("SLIME01", true).strength)
        << "red-hot sludge outshines brown";
    EXPECT_GT(wad::glowOf("LAVA1", true).strength, wad::glowOf("FWATER1", true).strength);
}

TEST(WadGlow, WeightsPickTheLitTexels) {
    // Every texel of a liquid; near-white or fully bright colours of a lamp, not its grey frame.
    EXPECT_EQ(wad::glowWeight(GlowKind::Whole, 10, 20, 5), 1.0f);
    EXPECT_EQ(wad::glowWeight(GlowKind::None, 255, 255, 255), 0.0f);
    EXPECT_EQ(wad::glowWeight(GlowKind::Bright, 255, 255, 255), 1.0f);
    EXPECT_EQ(wad::glowWeight(GlowKind::Bright, 0, 0, 255), 1.0f);    // LITEBLU's blue
    EXPECT_EQ(wad::glowWeight(GlowKind::Bright, 255, 0, 0), 1.0f);    // a lit switch light
    EXPECT_EQ(wad::glowWeight(GlowKind::Bright, 131, 31, 31), 0.0f);  // an unlit one
    EXPECT_EQ(wad::glowWeight(GlowKind::Bright, 150, 150, 150), 0.0f);
    // Panels: Freedoom's mid-bright green plate glows, its black grid does not.
    EXPECT_GT(wad::glowWeight(GlowKind::Panel, 83, 175, 71), 0.99f);
    EXPECT_EQ(wad::glowWeight(GlowKind::Panel, 39, 39, 39), 0.0f);
    // Screens: green text and blue displays glow; grey metal, wood and hazard yellow do not.
    EXPECT_GT(wad::glowWeight(GlowKind::Screen, 0, 200, 0), 0.99f);
    EXPECT_GT(wad::glowWeight(GlowKind::Screen, 20, 20, 200), 0.99f);
    EXPECT_EQ(wad::glowWeight(GlowKind::Screen, 140, 140, 140), 0.0f);
    EXPECT_EQ(wad::glowWeight(GlowKind::Screen, 150, 100, 60), 0.0f);
    EXPECT_EQ(wad::glowWeight(GlowKind::Screen, 230, 200, 20), 0.0f);
    // Monotone in brightness along a grey ramp, for each partial kind.
    for (GlowKind kind : {GlowKind::Bright, GlowKind::Panel, GlowKind::Screen})
        for (int v = 1; v < 256; ++v)
            EXPECT_GE(wad::glowWeight(kind, std::uint8_t(v), std::uint8_t(v), std::uint8_t(v)),
                      wad::glowWeight(kind, std::uint8_t(v - 1), std::uint8_t(v - 1),
                                      std::uint8_t(v - 1)));
}

TEST(WadGlow, GlowTextureScalesLinearLightByTheWeight) {
    Texture t;
    t.name = "LAMP";
    t.width = 3;
    t.height = 1;
    t.rgba = {255, 255, 255, 255, 100, 100, 100, 255, 200, 10, 10, 0};
    t.animation = {3, 1, 0.25f};
    Texture g = wad::glowTexture(t, GlowKind::Bright);
    EXPECT_EQ(g.name, "LAMP glow");
    EXPECT_EQ(g.animation.frames, 3);
    EXPECT_EQ(g.animation.frame, 1);
    EXPECT_EQ(std::vector<std::uint8_t>(g.rgba.begin(), g.rgba.begin() + 4),
              std::vector<std::uint8_t>(4, 255));
    EXPECT_EQ(std::vector<std::uint8_t>(g.rgba.begin() + 4, g.rgba.begin() + 8),
              (std::vector<std::uint8_t>{0, 0, 0, 255}));
    // A partial weight scales linear light, then re-encodes: 200 at weight w becomes
    // 255 * srgb(w * linear(200 / 255)).
    const float w = wad::glowWeight(GlowKind::Bright, 200, 10, 10);
    ASSERT_GT(w, 0.0f);
    ASSERT_LT(w, 1.0f);
    const float expected = 255.0f * shader::linearToSrgb(w * shader::srgbToLinear(200 / 255.0f));
    EXPECT_NEAR(g.rgba[8], expected, 0.51f);
    EXPECT_EQ(g.rgba[11], 0) << "alpha is kept";
}

TEST(WadSectorLight, CurveFollowsDoomsColormapsAtFourMetres) {
    EXPECT_FLOAT_EQ(wad::doomBrightness(255), 1.0f);
    EXPECT_FLOAT_EQ(wad::doomBrightness(240), 1.0f);
    EXPECT_FLOAT_EQ(wad::doomBrightness(192), 1.0f - 2.0f / 32);
    EXPECT_FLOAT_EQ(wad::doomBrightness(160), 1.0f - 10.0f / 32);
    EXPECT_FLOAT_EQ(wad::doomBrightness(128), 1.0f - 18.0f / 32);
    EXPECT_FLOAT_EQ(wad::doomBrightness(0), 1.0f / 32);
    EXPECT_FLOAT_EQ(wad::doomBrightness(-5), 1.0f / 32);
    EXPECT_FLOAT_EQ(wad::doomBrightness(400), 1.0f);
    for (int level = 1; level < 256; ++level)
        EXPECT_GE(wad::doomBrightness(level), wad::doomBrightness(level - 1));
    EXPECT_FLOAT_EQ(wad::sectorRadiance(160),
                    2.0f * shader::srgbToLinear(wad::doomBrightness(160)));
}

TEST(WadSky, TextureByEpisodeAndMap) {
    EXPECT_EQ(wad::skyTextureName("E1M1"), "SKY1");
    EXPECT_EQ(wad::skyTextureName("E3M9"), "SKY3");
    EXPECT_EQ(wad::skyTextureName("E4M2"), "SKY4");
    EXPECT_EQ(wad::skyTextureName("MAP01"), "SKY1");
    EXPECT_EQ(wad::skyTextureName("MAP11"), "SKY1");
    EXPECT_EQ(wad::skyTextureName("MAP12"), "SKY2");
    EXPECT_EQ(wad::skyTextureName("MAP20"), "SKY2");
    EXPECT_EQ(wad::skyTextureName("MAP21"), "SKY3");
    EXPECT_EQ(wad::skyTextureName("MAP32"), "SKY3");
    EXPECT_EQ(wad::skyTextureName("START"), "SKY1");
}

// A 256x128 sky whose texel (x, y) encodes its column in red and its row in green.
Texture codedSky() {
    Texture t;
    t.name = "SKY1";
    t.width = 256;
    t.height = 128;
    t.rgba.resize(256 * 128 * 4);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 256; ++x) {
            std::uint8_t* p = &t.rgba[std::size_t(y * 256 + x) * 4];
            p[0] = std::uint8_t(x), p[1] = std::uint8_t(y), p[2] = 77, p[3] = 255;
        }
    return t;
}

// The texel of the coded sky a direction shows: (column, row) decoded back from the map.
std::pair<int, int> shownTexel(const EnvironmentMap& map, Vec3 direction) {
    Environment env;
    env.map = map;
    const Vec3 c = environmentRadiance(env, Vec3{0}, direction) / 2.0f;  // brightness 2
    auto decode = [](float linear) {
        return int(std::lround(shader::linearToSrgb(linear) * 255.0f));
    };
    return {decode(c.x), decode(c.y)};
}

Vec3 doomDirection(double angleDegrees, double elevationDegrees) {
    const double a = degreesToRadians(angleDegrees),
                 e = degreesToRadians(elevationDegrees);
    // Doom (x, y) is our (x, -z).
    return Vec3{float(std::cos(e) * std::cos(a)), float(std::sin(e)),
                float(-std::cos(e) * std::sin(a))};
}

TEST(WadSky, MapWrapsTheSkyFourTimesWithRowHundredOnTheHorizon) {
    const EnvironmentMap map = wad::skyEnvironment(codedSky(), 2.0f);
    ASSERT_EQ(map.width, wad::kSkyMapWidth);
    ASSERT_EQ(map.height, wad::kSkyMapHeight);
    // Column: 1024 per turn from east (Doom angle 0), the 256-wide texture 4 times; a little off
    // the exact angles so that rounding cannot pick the neighbouring column.
    EXPECT_EQ(shownTexel(map, doomDirection(0.1, 0.1)).first, 0);
    EXPECT_EQ(shownTexel(map, doomDirection(45.1, 0.1)).first, 128);
    EXPECT_EQ(shownTexel(map, doomDirection(90.1, 0.1)).first, 0);
    EXPECT_EQ(shownTexel(map, doomDirection(200.1, 0.1)).first, int(200.1 / 360 * 1024) % 256);
    // Row: 100 - 160 tan(elevation), so just above the horizon row 99, and 20 degrees up row 41.
    EXPECT_EQ(shownTexel(map, doomDirection(10, 0.2)).second, 99);
    const int row20 = int(std::floor(100 - 160 * std::tan(degreesToRadians(20.0))));
    EXPECT_NEAR(shownTexel(map, doomDirection(10, 20)).second, row20,
                1);  // the map's rows are 0.35 degrees
    const int rowBelow = int(std::floor(100 + 160 * std::tan(degreesToRadians(5.0))));
    EXPECT_NEAR(shownTexel(map, doomDirection(10, -5)).second, rowBelow, 1);
    // Straight up: the mean of the top 4 rows (rows 0-3: green 1.5 on average, decoded first).
    Environment env;
    env.map = map;
    const Vec3 up = environmentRadiance(env, Vec3{0}, Vec3{0, 1, 0}) / 2.0f;
    float greenMean = 0;
    for (int row = 0; row < 4; ++row) greenMean += shader::srgbToLinear(row / 255.0f) / 4;
    EXPECT_NEAR(up.y, greenMean, 1e-6f);
    EXPECT_NEAR(up.z, shader::srgbToLinear(77 / 255.0f), 1e-6f);
    // Everything finite and non-negative: a valid environment.
    Environment valid;
    valid.map = map;
    EXPECT_NO_THROW(validateEnvironment(valid));
}

TEST(WadAnimation, CyclesRunFromFirstToLastInWadOrder) {
    // A frame added between the ends belongs to the cycle; a backwards cycle is none.
    const std::vector<std::string> flats = {"FLOOR1",  "NUKAGE1", "EXTRA",  "NUKAGE2",
                                            "NUKAGE3", "FWATER4", "FWATER1"};
    const auto cycles = wad::findCycles(flats, false);
    ASSERT_EQ(cycles.size(), 1u);
    EXPECT_EQ(cycles[0], (std::vector<std::string>{"NUKAGE1", "EXTRA", "NUKAGE2", "NUKAGE3"}));
    EXPECT_TRUE(wad::findCycles(flats, true).empty()) << "flat cycles are not texture cycles";
    EXPECT_FLOAT_EQ(wad::kSecondsPerAnimationFrame, 8.0f / 35.0f);
}

// A room floored with NUKAGE2 (of NUKAGE1-3) and walled with FIREBLU1 (of FIREBLU1-2).
std::string animatedWad() {
    Graphics g;
    g.texture("FIREBLU1", testing::picture(8, 8, [](int, int) { return 200; }));
    g.texture("FIREBLU2", testing::picture(8, 8, [](int, int) { return 210; }));
    for (int k = 1; k <= 3; ++k)
        g.flat("NUKAGE" + std::to_string(k), [k](int, int) { return 10 * k; });
    MapBuilder m;
    int s = m.sector(0, 128, "NUKAGE2", "NUKAGE2", 160);
    m.loop({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, s, "FIREBLU1");
    m.thing(64, 64, 90, 1);
    WadBuilder wad;
    m.addTo(wad, "E1M1");
    g.addTo(wad);
    return wad.build("IWAD");
}

TEST(WadAnimation, ACycleBringsItsFramesConsecutively) {
    Scene scene = loadWadFromMemory(animatedWad(), "E1M1", "anim.wad");
    int nukage2 = -1, fire1 = -1;
    for (const Material& m : scene.materials) {
        if (m.name == "flat NUKAGE2") nukage2 = m.albedoTexture.texture;
        if (m.name == "wall FIREBLU1") fire1 = m.albedoTexture.texture;
    }
    ASSERT_GE(nukage2, 1);
    ASSERT_GE(fire1, 0);
    for (int k = 0; k < 3; ++k) {
        const Texture& t = scene.textures[std::size_t(nukage2 - 1 + k)];
        EXPECT_EQ(t.name, "NUKAGE" + std::to_string(k + 1));
        EXPECT_EQ(t.animation.frames, 3);
        EXPECT_EQ(t.animation.frame, k);
        EXPECT_FLOAT_EQ(t.animation.secondsPerFrame, 8.0f / 35.0f);
        EXPECT_EQ(t.rgba[0], 10 * (k + 1)) << "palette index 10k is red 10k";
    }
    EXPECT_EQ(scene.textures[std::size_t(fire1)].animation.frames, 2);
    EXPECT_EQ(scene.textures[std::size_t(fire1 + 1)].name, "FIREBLU2");
    // Nukage glows in its own colours (the frames themselves are its emission texture); Doom's
    // nearest texel is the default filter.
    for (const Material& m : scene.materials)
        if (m.name == "flat NUKAGE2") {
            EXPECT_TRUE(m.isEmissive());
            EXPECT_EQ(m.emissionTexture.texture, nukage2);
            EXPECT_EQ(m.albedoTexture.filter, Filter::Nearest);
        }
    WadOptions bilinear;
    bilinear.filter = Filter::Linear;
    for (const Material& m :
         loadWadFromMemory(animatedWad(), "E1M1", "anim.wad", bilinear).materials)
        if (m.albedoTexture.present()) {
            EXPECT_EQ(m.albedoTexture.filter, Filter::Linear) << m.name;
        }
}

// The clock the shaders pick frames with and the viewer restarts its mean by: whole frames shown
// since time 0, and 0 for a still texture or a time that is no number of seconds.
TEST(WadAnimation, ClockTicksOncePerFrameTime) {
    const float tic = 8.0f / 35.0f;
    EXPECT_EQ(shader::animationTick(0.0f, tic), 0u);
    EXPECT_EQ(shader::animationTick(0.99f * tic, tic), 0u);
    EXPECT_EQ(shader::animationTick(1.01f * tic, tic), 1u);
    EXPECT_EQ(shader::animationTick(10.5f * tic, tic), 10u);
    EXPECT_EQ(shader::animationTick(1e6f, tic), std::uint32_t(std::floor(1e6f / tic)));
    EXPECT_EQ(shader::animationTick(5.0f, 0.0f), 0u);
    EXPECT_EQ(shader::animationTick(-1.0f, tic), 0u);
    EXPECT_EQ(shader::animationTick(std::nanf(""), tic), 0u);
    EXPECT_EQ(shader::animationTick(1e30f, tic), 4294967040u);
}

TEST(WadAnimation, SceneValidationKeepsCyclesInRange) {
    Scene scene = loadWadFromMemory(animatedWad(), "E1M1", "anim.wad");
    scene.textures.back().animation = {4, 0, 0.2f};  // runs past the last texture
    EXPECT_THROW(scene.validate(), Error);
    scene.textures.back().animation = {2, 1, 0.0f};  // no duration
    EXPECT_THROW(scene.validate(), Error);
}

// Sprite TROO frame A: 8 views from 5 lumps (2, 3, 4 mirrored as 8, 7, 6), each view a 4x6
// picture of one palette index (20 + view) with offsets (2, 6), so the thing stands on the floor.
// Its left column is index 100 to tell mirrored views apart. BAR1 frame A has one view.
std::string spriteWad() {
    Graphics g;
    g.texture("WALL1", testing::picture(8, 8, [](int, int) { return 128; }));
    g.flat("FLOOR1", [](int, int) { return 128; });
    auto view = [](int v) {
        return testing::picture(
            4, 6, [v](int x, int) { return x == 0 ? 100 : 20 + v; }, 2, 6);
    };
    g.sprites = {
        {"TROOA1", view(1)},
        {"TROOA2A8", view(2)},
        {"TROOA3A7", view(3)},
        {"TROOA4A6", view(4)},
        {"TROOA5", view(5)},
        {"BAR1A0", testing::picture(
                       3, 5, [](int x, int y) { return (x == 1 && y == 2) ? -1 : 50; }, 1, 5)}};
    MapBuilder m;
    int s = m.sector(16, 128, "FLOOR1", "FLOOR1", 160);
    m.loop({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, s, "WALL1");
    m.thing(64, 64, 90, 1);
    m.thing(128, 128, 45, 3001);  // an imp
    m.thing(100, 160, 0, 2035);   // a barrel
    m.thing(160, 100, 0, 3004);   // a zombieman: no POSS in this WAD, so no sprite
    WadBuilder wad;
    m.addTo(wad, "E1M1");
    g.addTo(wad);
    return wad.build("IWAD");
}

TEST(WadSprites, ThingsBecomeSpritesWithTheirViews) {
    Scene scene = loadWadFromMemory(spriteWad(), "E1M1", "sprites.wad");
    ASSERT_EQ(scene.sprites.size(), 2u) << "the zombieman has no picture in this WAD";
    const Sprite& imp = scene.sprites[0];
    const Sprite& barrel = scene.sprites[1];
    EXPECT_EQ(imp.rotations, 8u);
    EXPECT_EQ(barrel.rotations, 1u);
    // On the floor (16 units) at the thing's place, facing its angle (45 degrees: +x and -z).
    EXPECT_NEAR(imp.position.x, 4.0f, 1e-6f);
    EXPECT_NEAR(imp.position.y, 0.5f, 1e-6f);
    EXPECT_NEAR(imp.position.z, -4.0f, 1e-6f);
    EXPECT_NEAR(imp.facing.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(imp.facing.z, -std::sqrt(0.5f), 1e-6f);
    // The cell: x from -2 to 2 and y from 0 to 6 units, with a 1-texel border all round.
    EXPECT_FLOAT_EQ(imp.left, -3 / 32.0f);
    EXPECT_FLOAT_EQ(imp.right, 3 / 32.0f);
    EXPECT_FLOAT_EQ(imp.bottom, -1 / 32.0f);
    EXPECT_FLOAT_EQ(imp.top, 7 / 32.0f);
    const Material& m = scene.materials[imp.material];
    EXPECT_GT(m.alphaCutoff, 0.0f);
    EXPECT_FALSE(m.isEmissive()) << "imps are not full bright";
    const Texture& atlas = scene.textures[std::size_t(m.albedoTexture.texture)];
    ASSERT_EQ(atlas.width, 8 * 6);
    ASSERT_EQ(atlas.height, 8);
    auto texel = [&](int x, int y) { return atlas.rgba[std::size_t(y * atlas.width + x) * 4]; };
    auto alpha = [&](int x, int y) { return atlas.rgba[std::size_t(y * atlas.width + x) * 4 + 3]; };
    for (int v = 1; v <= 8; ++v) {
        const int cell = (v - 1) * 6;
        const int source = v <= 5 ? v : 10 - v;  // 6, 7, 8 are 4, 3, 2 mirrored
        const bool mirrored = v > 5;
        EXPECT_EQ(alpha(cell, 3), 0) << "border, view " << v;
        EXPECT_EQ(texel(cell + 1, 3), mirrored ? 20 + source : 100) << "view " << v;
        EXPECT_EQ(texel(cell + 4, 3), mirrored ? 100 : 20 + source) << "view " << v;
        EXPECT_EQ(alpha(cell + 2, 0), 0) << "top border, view " << v;
    }
    // The barrel's hole stays transparent.
    const Texture& bar =
        scene.textures[std::size_t(scene.materials[barrel.material].albedoTexture.texture)];
    EXPECT_EQ(bar.width, 5);
    EXPECT_EQ(bar.rgba[std::size_t(3 * 5 + 2) * 4 + 3], 0);
    EXPECT_EQ(bar.rgba[std::size_t(3 * 5 + 1) * 4 + 3], 255);
}

TEST(WadSprites, ThingTableAndSkill) {
    ASSERT_NE(wad::thingType(2028), nullptr);
    EXPECT_TRUE(wad::thingType(2028)->fullBright);
    EXPECT_EQ(std::string(wad::thingType(3001)->sprite), "TROO");
    EXPECT_EQ(wad::thingType(15)->frame, 'N') << "a dead player lies in its last frame";
    EXPECT_EQ(wad::thingType(63)->hangHeight, 68);
    EXPECT_EQ(wad::thingType(1), nullptr) << "player starts are not drawn";
    EXPECT_EQ(wad::thingType(14), nullptr) << "nor are teleport destinations";
    EXPECT_TRUE(wad::inSinglePlayerMedium(7));
    EXPECT_FALSE(wad::inSinglePlayerMedium(4)) << "hard only";
    EXPECT_FALSE(wad::inSinglePlayerMedium(7 | 16)) << "multiplayer only";
}

TEST(WadOptionsTest, ScalesAreChecked) {
    WadOptions o;
    o.glow = -1;
    EXPECT_THROW(validateWadOptions(o), UsageError);
    o.glow = 1;
    o.sectorLight = std::nanf("");
    EXPECT_THROW(validateWadOptions(o), UsageError);
    // Off: nothing glows and no fill light; the sky ceilings stay portals.
    o.glow = 0;
    o.sectorLight = 0;
    Scene scene = loadWadFromMemory(animatedWad(), "E1M1", "anim.wad", o);
    for (const Material& m : scene.materials) EXPECT_FALSE(m.isEmissive()) << m.name;
}

}  // namespace
}  // namespace penumbra
