// The dungeon preset through the real shaders (issue 40): its walls show Freedoom's texture in the
// albedo guide (and the flat-coloured dungeon does not: the same measure tells them apart), its
// torch panels glow at their emission, the floor in front of a torch is lit far more than the
// floor of the tile farthest from every torch, and no sample is NaN. The camera torch is not
// attached (only the panels light the level). Needs freedoom1.wad: skipped without it, failed
// under CI.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../unit/io/io_test_util.h"
#include "gpu_fixture.h"
#include "render/final_passes.h"
#include "render/renderer.h"
#include "render_helpers.h"
#include "scene/presets/dungeon_textures.h"
#include "scene/presets/presets.h"

namespace penumbra::test {
namespace {

const Mesh& meshNamed(const Scene& s, const std::string& name) {
    for (const Mesh& m : s.meshes)
        if (m.name == name) return m;
    throw std::runtime_error("no mesh " + name);
}

void aim(Scene& scene, Vec3 position, Vec3 lookAt, Vec3 up, float fov) {
    scene.camera.position = position;
    scene.camera.lookAt = lookAt;
    scene.camera.up = up;
    scene.camera.fovYDegrees = fov;
}

// The first torch panel: its centre and the direction its glowing face looks (into the room).
struct Panel {
    Vec3 centre, front;
};
Panel firstPanel(const Scene& s) {
    const Mesh& m = meshNamed(s, "wall torches");
    Vec3 sum{0};
    for (std::size_t i = 0; i < 4; ++i) sum = sum + m.positions[i];
    const Vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]], c = m.positions[m.indices[2]];
    return {sum * 0.25f, normalize(cross(b - a, c - a))};
}

// Looking straight at the first torch panel from 5 m in front of it, at its height.
void facePanel(Scene& s) {
    const Panel p = firstPanel(s);
    aim(s, p.centre + p.front * 5.0f, p.centre, {0, 1, 0}, 60.0f);
}

// Of the pixels whose centre sees the wall around the panel (normal facing the camera, albedo
// not the panel's), the share whose textured albedo is more than 3% off the median: near 1 for a
// texture, only the pixels that straddle an edge for a flat colour.
float wallAlbedoVariation(const gpu::Context& ctx, const Scene& scene, std::uint32_t w, std::uint32_t h) {
    Renderer renderer(ctx, scene, testSettings(w, h, 1, 1));
    FinalFramePasses passes(ctx, renderer);
    const FrameGuides g = passes.guides();
    const Vec3 panelAlbedo = scene.materials[meshNamed(scene, "wall torches").material].albedo;
    const Vec3 toCamera = normalize(scene.camera.position - scene.camera.lookAt);
    std::vector<float> wall;
    for (std::size_t i = 0; i < g.albedo.size(); ++i)
        if (dot(g.normal[i], toCamera) > 0.99f && length(g.albedo[i] - panelAlbedo) > 0.02f)
            wall.push_back(luminance(g.albedo[i]));
    EXPECT_GT(wall.size(), std::size_t(w) * h / 4) << "the wall fills the view";
    if (wall.empty()) return 0;
    std::vector<float> sorted = wall;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    const float median = sorted[sorted.size() / 2];
    const auto off = std::count_if(wall.begin(), wall.end(), [&](float a) { return std::abs(a - median) > 0.03f * median; });
    return float(off) / float(wall.size());
}

ImageRgb render(const gpu::Context& ctx, const Scene& scene, RenderSettings settings) {
    Renderer r(ctx, scene, settings);
    r.render();
    EXPECT_EQ(r.stats().invalidSamples, 0u);
    ImageRgb image = r.image();
    EXPECT_FALSE(image.hasNonFinite());
    return image;
}

// The mean radiance of the floor seen straight down from eye height above the centre of tile (x, z).
float floorBrightness(const gpu::Context& ctx, Scene scene, int x, int z) {
    const TileGrid& grid = *scene.tileGrid;
    const Vec3 centre = grid.origin + Vec3{(float(x) + 0.5f) * grid.tileSize, 0, (float(z) + 0.5f) * grid.tileSize};
    aim(scene, centre + Vec3{0, grid.eyeHeight, 0}, centre, {0, 0, -1}, 30.0f);
    return luminance(render(ctx, scene, testSettings(16, 16, 64, 4)).mean());
}

TEST_F(GpuTest, DungeonIsTexturedFromFreedoom) {
    PENUMBRA_REQUIRE_ASSET(freedoomWadPath());
    Scene textured = makePreset("dungeon");
    facePanel(textured);
    Scene flat = makeDungeon("/nonexistent/freedoom1.wad");
    facePanel(flat);
    const float t = wallAlbedoVariation(*ctx, textured, 64, 40);
    const float f = wallAlbedoVariation(*ctx, flat, 64, 40);
    RecordProperty("textured_share", std::to_string(t));
    RecordProperty("flat_share", std::to_string(f));
    EXPECT_GT(t, 0.3f) << "textured walls: share of wall pixels off the median albedo";
    EXPECT_LT(f, 0.1f) << "flat-coloured walls: only edge pixels should differ";
}

TEST_F(GpuTest, DungeonTorchPanelsGlowAndLightTheRoomNearThem) {
    PENUMBRA_REQUIRE_ASSET(freedoomWadPath());
    Scene scene = makePreset("dungeon");
    ASSERT_TRUE(scene.lights.empty());  // no point lights: the panels are the light
    facePanel(scene);
    const ImageRgb image = render(*ctx, scene, testSettings(64, 40, 16, 4));
    // The middle of the image is the middle of the panel: its emission, plus the little light it
    // reflects (others panels' and the walls').
    const Vec3 emission = scene.materials[meshNamed(scene, "wall torches").material].emission;
    for (int y : {19, 20})
        for (int x : {31, 32}) {
            const Vec3 p = image.at(x, y);
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(p[k], 0.97f * emission[k]) << "pixel " << x << "," << y << " channel " << k;
                EXPECT_LE(p[k], 1.3f * emission[k]) << "pixel " << x << "," << y << " channel " << k;
            }
        }
    // Nothing in view is brighter than a panel.
    float brightest = 0;
    for (const Vec3& p : image.pixels) brightest = std::max(brightest, luminance(p));
    EXPECT_LE(brightest, 1.3f * luminance(emission));

    // The floor one tile in front of the panel against the floor of the tile farthest from every panel.
    const TileGrid& grid = *scene.tileGrid;
    const Panel panel = firstPanel(scene);
    const Vec3 inFront = panel.centre + panel.front * (0.5f * grid.tileSize);
    const int nearX = int(std::floor(inFront.x / grid.tileSize)), nearZ = int(std::floor(inFront.z / grid.tileSize));
    const Mesh& panels = meshNamed(scene, "wall torches");
    int farX = -1, farZ = -1;
    float farthest = 0;
    for (int z = 0; z < grid.depth; ++z)
        for (int x = 0; x < grid.width; ++x) {
            if (!grid.canStand(x, z)) continue;
            const Vec3 c{(float(x) + 0.5f) * grid.tileSize, 1.5f, (float(z) + 0.5f) * grid.tileSize};
            float nearest = std::numeric_limits<float>::infinity();
            for (const Vec3& p : panels.positions) nearest = std::min(nearest, length(p - c));
            if (nearest > farthest) farthest = nearest, farX = x, farZ = z;
        }
    ASSERT_TRUE(grid.canStand(nearX, nearZ));
    ASSERT_GT(farthest, 4.0f);  // metres: the map has corners far from every torch
    const float lit = floorBrightness(*ctx, scene, nearX, nearZ);
    const float dark = floorBrightness(*ctx, scene, farX, farZ);
    RecordProperty("lit_over_dark", std::to_string(lit / std::max(dark, 1e-9f)));
    EXPECT_GT(lit, 0.0f);
    EXPECT_GT(lit, 4.0f * dark) << "near tile " << nearX << "," << nearZ << " far tile " << farX << "," << farZ;
}

}  // namespace
}  // namespace penumbra::test
