// The Doom look through the real shaders, on small WADs written here (tests/unit/wad/
// wad_builder.h): glowing textures light a floor with only their lit texels, sector light levels
// order the brightness of identical rooms, the sky shows through a sky ceiling and lights the
// room, nearest lookup returns texels exactly, an animated flat changes with time, and sprites
// are see-through where their texels are and show the view the camera's side picks. Nothing is
// lit by the torch (never attached here) or by lamps (there are none).
#include <cmath>
#include <string>

#include "../unit/wad/wad_builder.h"
#include "gpu_fixture.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/io/wad/sector_light.h"
#include "scene/io/wad/wad_loader.h"
#include "shared/color.h"

namespace penumbra::test {
namespace {
using testing::Graphics;
using testing::MapBuilder;
using testing::WadBuilder;

// The linear colour of palette index i of the test palette (i, 255 - i, i / 2).
Vec3 paletteLinear(int i) {
    return {shader::srgbToLinear(float(i) / 255), shader::srgbToLinear(float(255 - i) / 255),
            shader::srgbToLinear(float(i / 2) / 255)};
}

std::string solid(int width, int height, int index, int left = 0, int top = 0) {
    return testing::picture(
        width, height, [index](int, int) { return index; }, left, top);
}

// A square room of `size` units (x and y from 0), walls WALL1 except the north one, floor and
// ceiling flats as given.
void room(MapBuilder& m, int x0, int size, int sector, const std::string& north) {
    const int a = m.vertex(x0, 0), b = m.vertex(x0, size), c = m.vertex(x0 + size, size),
              d = m.vertex(x0 + size, 0);
    m.line(a, b, m.side(sector, "-", "-", "WALL1"));
    m.line(b, c, m.side(sector, "-", "-", north));  // y = size: north, our -z
    m.line(c, d, m.side(sector, "-", "-", "WALL1"));
    m.line(d, a, m.side(sector, "-", "-", "WALL1"));
}

std::string build(const MapBuilder& m, const Graphics& g) {
    WadBuilder wad;
    m.addTo(wad, "E1M1");
    g.addTo(wad);
    return wad.build("IWAD");
}

Graphics plainGraphics() {
    Graphics g;
    g.texture("WALL1", solid(8, 8, 128));
    g.flat("FLOOR1", [](int, int) { return 128; });
    return g;
}

void aim(Scene& scene, Vec3 position, Vec3 lookAt, float fov) {
    scene.camera.position = position;
    scene.camera.lookAt = lookAt;
    scene.camera.up = {0, 1, 0};
    scene.camera.fovYDegrees = fov;
}

ImageRgb render(const gpu::Context& ctx, const Scene& scene, RenderSettings settings) {
    Renderer r(ctx, scene, settings);
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    return r.image();
}

bool near(Vec3 a, Vec3 b, float tolerance) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(a[k] - b[k]) > tolerance * std::max(1.0f, std::abs(b[k]))) return false;
    return true;
}

// LITE3 on the north wall: 8 columns of index 255 (near-white in brightness: it glows) beside 8
// of index 128 (half bright: it does not). No sector light, so the wall is the only light.
std::string glowWad() {
    Graphics g = plainGraphics();
    g.texture("LITE3", testing::picture(16, 16, [](int x, int) { return x < 8 ? 255 : 128; }));
    MapBuilder m;
    room(m, 0, 256, m.sector(0, 128, "FLOOR1", "FLOOR1", 255), "LITE3");
    m.thing(128, 128, 90, 1);
    return build(m, g);
}

TEST_F(GpuTest, GlowingWallTextureLightsTheFloorWithItsLitTexelsOnly) {
    WadOptions noSectorLight;
    noSectorLight.sectorLight = 0;
    Scene scene = loadWadFromMemory(glowWad(), "E1M1", "glow.wad", noSectorLight);
    // Seen straight on with emission only: every pixel is a lit texel's emission (6 x its colour,
    // (255, 0, 127)) or nothing, never the half-bright texels, and both appear.
    aim(scene, {4, 2, -4}, {4, 2, -8}, 30);
    const Vec3 lit = paletteLinear(255) * 6.0f;
    ImageRgb wall = render(*ctx, scene, testSettings(24, 8, 1, 0));
    int litPixels = 0, darkPixels = 0;
    for (const Vec3& p : wall.pixels) {
        if (near(p, lit, 1e-4f))
            ++litPixels;
        else if (near(p, Vec3{0}, 1e-6f))
            ++darkPixels;
        else
            ADD_FAILURE() << "pixel " << p.x << "," << p.y << "," << p.z
                          << " is neither a lit texel nor dark";
    }
    EXPECT_GT(litPixels, 24 * 8 / 5);
    EXPECT_GT(darkPixels, 24 * 8 / 5);

    // The floor in front of the wall is lit, by light with no green in it: the half-bright
    // texels (128, 127, 64), which have green, emit nothing.
    aim(scene, {4, 2, -6}, {4, 0, -7.5f}, 30);
    ImageRgb floor = render(*ctx, scene, testSettings(8, 8, 8, 1));
    const Vec3 mean = floor.mean();
    EXPECT_GT(mean.x, 0.02f) << "the floor next to the glowing wall is dark";
    EXPECT_EQ(mean.y, 0.0f);
    // With --wad-glow 0 nothing lights it.
    WadOptions off = noSectorLight;
    off.glow = 0;
    Scene dark = loadWadFromMemory(glowWad(), "E1M1", "glow.wad", off);
    dark.camera = scene.camera;
    EXPECT_EQ(render(*ctx, dark, testSettings(8, 8, 8, 1)).mean(), Vec3{0});
}

// Two identical rooms far apart, at light levels 255 and 144: the only light is each sector's
// fill, and light transport is linear, so the images' means stand in the ratio of the fills.
TEST_F(GpuTest, SectorLightLevelsOrderIdenticalRoomsByBrightness) {
    MapBuilder m;
    room(m, 0, 256, m.sector(0, 128, "FLOOR1", "FLOOR1", 255), "WALL1");
    room(m, 1024, 256, m.sector(0, 128, "FLOOR1", "FLOOR1", 144), "WALL1");
    m.thing(128, 128, 90, 1);
    Scene scene = loadWadFromMemory(build(m, plainGraphics()), "E1M1", "rooms.wad");
    const RenderSettings settings = testSettings(8, 8, 64, 3);
    MeanEstimate means[2];
    for (int k = 0; k < 2; ++k) {
        const float x = 4.0f + 32.0f * float(k);
        aim(scene, {x - 2, 2, -2}, {x + 1, 0.5f, -6}, 60);
        Renderer r(*ctx, scene, settings);
        r.render();
        means[k] = imageMean(r.accumulation(), settings.samplesPerPixel);
    }
    ASSERT_GT(means[1].mean, 0.0);
    EXPECT_GT(means[0].mean, means[1].mean);
    const double expected = wad::sectorRadiance(255) / wad::sectorRadiance(144);
    const double ratio = means[0].mean / means[1].mean;
    const double sigma =
        ratio * std::hypot(means[0].stderr / means[0].mean, means[1].stderr / means[1].mean);
    EXPECT_NEAR(ratio, expected, 5 * sigma) << "sigma " << sigma;
}

// A 64 m square yard under F_SKY1 at 16 m, with a sky whose top rows are all index 90: looking
// up, the camera sees that colour (the sky's cap) through the ceiling, not the sector's fill
// light, and the sky alone lights the yard.
std::string skyWad() {
    Graphics g = plainGraphics();
    g.texture("SKY1", testing::picture(256, 128,
                                       [](int x, int y) { return y < 8 ? 90 : 20 + x / 64 * 40; }));
    MapBuilder m;
    room(m, 0, 2048, m.sector(0, 512, "FLOOR1", "F_SKY1", 200), "WALL1");
    m.thing(1024, 1024, 90, 1);
    return build(m, g);
}

TEST_F(GpuTest, SkyTextureShowsThroughSkyCeilingAndLightsTheFloor) {
    Scene scene = loadWadFromMemory(skyWad(), "E1M1", "sky.wad");
    ASSERT_TRUE(scene.environment.map.has_value());
    aim(scene, {32, 1.5f, -32}, {32.5f, 10, -32.2f}, 20);
    ImageRgb up = render(*ctx, scene, testSettings(8, 8, 1, 0));
    const Vec3 sky = paletteLinear(90);
    for (const Vec3& p : up.pixels)
        EXPECT_TRUE(near(p, sky, 1e-4f)) << p.x << "," << p.y << "," << p.z;

    WadOptions skyOnly;
    skyOnly.sectorLight = 0;
    Scene yard = loadWadFromMemory(skyWad(), "E1M1", "sky.wad", skyOnly);
    aim(yard, {32, 1.5f, -32}, {33, 0, -33}, 30);
    EXPECT_GT(luminance(render(*ctx, yard, testSettings(8, 8, 8, 1)).mean()), 1e-3f)
        << "the sky lights nothing";
}

// A floor of NUKAGE1-3 (hot liquid: emission 4 x its own colours) seen from above, emission only.
std::string nukageWad(int checkerA, int checkerB) {
    Graphics g = plainGraphics();
    g.flat("NUKAGE1", [=](int x, int y) { return (x + y) % 2 ? checkerA : checkerB; });
    g.flat("NUKAGE2", [](int, int) { return 70; });
    g.flat("NUKAGE3", [](int, int) { return 110; });
    MapBuilder m;
    room(m, 0, 256, m.sector(0, 128, "NUKAGE1", "FLOOR1", 160), "WALL1");
    m.thing(128, 128, 90, 1);
    return build(m, g);
}

TEST_F(GpuTest, NearestLookupReturnsExactTexelColours) {
    // One sample per pixel of a one-texel checker: nearest gives one texel or the other exactly;
    // bilinear mostly blends them.
    const Vec3 a = paletteLinear(250) * 4.0f, b = paletteLinear(30) * 4.0f;
    for (Filter filter : {Filter::Nearest, Filter::Linear}) {
        WadOptions options;
        options.filter = filter;
        Scene scene = loadWadFromMemory(nukageWad(250, 30), "E1M1", "nukage.wad", options);
        aim(scene, {4, 1, -4}, {4, 0, -4.05f}, 20);
        int exact = 0;
        const ImageRgb img = render(*ctx, scene, testSettings(16, 16, 1, 0));
        for (const Vec3& p : img.pixels) exact += near(p, a, 1e-4f) || near(p, b, 1e-4f);
        if (filter == Filter::Nearest)
            EXPECT_EQ(exact, 16 * 16);
        else
            EXPECT_LT(exact, 16 * 16 / 4);
    }
}

TEST_F(GpuTest, AnimatedFlatChangesWithTime) {
    Scene scene = loadWadFromMemory(nukageWad(30, 30), "E1M1", "nukage.wad");
    aim(scene, {4, 1, -4}, {4, 0, -4.05f}, 20);
    // 8 tics of 1/35 s per frame: NUKAGE1 until 0.229 s, then NUKAGE2, then NUKAGE3, then again.
    const struct {
        float time;
        int index;
    } moments[] = {{0.0f, 30}, {0.3f, 70}, {0.5f, 110}, {0.7f, 30}};
    for (const auto& m : moments) {
        RenderSettings settings = testSettings(4, 4, 1, 0);
        settings.time = m.time;
        const ImageRgb img = render(*ctx, scene, settings);
        for (const Vec3& p : img.pixels)
            EXPECT_TRUE(near(p, paletteLinear(m.index) * 4.0f, 1e-4f))
                << "time " << m.time << ": " << p.x;
    }
}

// Sprites: a floor lamp (full bright) whose picture is transparent on its left half, in front of
// a wall of FIREBLU1 (fire: emission 4 x its colour); and a lost soul (full bright, 8 views of
// colours 20 + 20 v) seen from four sides.
std::string spriteWad() {
    Graphics g = plainGraphics();
    g.texture("FIREBLU1", solid(8, 8, 60));
    g.sprites = {{"COLUA0", testing::picture(
                                32, 32, [](int x, int) { return x < 16 ? -1 : 200; }, 16, 32)}};
    for (int v = 1; v <= 8; ++v)
        g.sprites.push_back({"SKULA" + std::to_string(v), solid(16, 16, 20 + 20 * v, 8, 16)});
    MapBuilder m;
    room(m, 0, 256, m.sector(0, 128, "FLOOR1", "FLOOR1", 160), "FIREBLU1");
    room(m, 1024, 256, m.sector(0, 128, "FLOOR1", "FLOOR1", 160), "WALL1");
    m.thing(128, 40, 90, 1);
    m.thing(128, 128, 0, 2028);   // the lamp
    m.thing(1152, 128, 0, 3006);  // the lost soul, facing east
    return build(m, g);
}

TEST_F(GpuTest, SpriteTransparentTexelsLetRaysThrough) {
    WadOptions options;
    options.sectorLight = 0;
    Scene scene = loadWadFromMemory(spriteWad(), "E1M1", "sprites.wad", options);
    ASSERT_EQ(scene.sprites.size(), 2u);
    // From 2.75 m south of the lamp at half its height, looking north: the sprite covers about
    // +-11 pixels around the middle of a 32-pixel, 30-degree view.
    aim(scene, {4, 0.5f, -1.25f}, {4, 0.5f, -8}, 30);
    const ImageRgb img = render(*ctx, scene, testSettings(32, 32, 1, 0));
    const Vec3 fire = paletteLinear(60) * 4.0f, lamp = paletteLinear(200);
    for (int x : {9, 11, 13})
        EXPECT_TRUE(near(img.at(x, 16), fire, 1e-4f)) << "x " << x << ": the hole hides the wall";
    for (int x : {19, 21, 23})
        EXPECT_TRUE(near(img.at(x, 16), lamp, 1e-4f)) << "x " << x << ": the lamp is not drawn";
    EXPECT_TRUE(near(img.at(16, 3), fire, 1e-4f)) << "above the lamp";
}

TEST_F(GpuTest, SpriteShowsTheViewOfTheCamerasSide) {
    Scene scene = loadWadFromMemory(spriteWad(), "E1M1", "sprites.wad");
    // The soul stands at (1152, 128) facing east (+x); Doom's rule gives view 1 from the east,
    // 3 from the north (our -z), 5 from the west and 7 from the south.
    const Vec3 soul{36, 0.25f, -4};
    const struct {
        Vec3 offset;
        int view;
    } sides[] = {{{2, 0, 0}, 1}, {{0, 0, -2}, 3}, {{-2, 0, 0}, 5}, {{0, 0, 2}, 7}};
    Renderer renderer(*ctx, scene, testSettings(4, 4, 1, 0));  // one pipeline for the four views
    for (const auto& side : sides) {
        aim(scene, soul + side.offset, soul, 10);
        renderer.restart(scene.camera);
        renderer.render();
        const ImageRgb img = renderer.image();
        EXPECT_TRUE(near(img.at(2, 2), paletteLinear(20 + 20 * side.view), 1e-4f))
            << "view " << side.view;
    }
}

}  // namespace
}  // namespace penumbra::test
