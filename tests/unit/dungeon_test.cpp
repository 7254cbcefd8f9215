// The dungeon preset: one map, no per-tile copies, glowing torch panels on walls, Freedoom's
// textures (flat colours without the WAD), and a phantom that patrols its corridor on walkable
// tiles (a scene motion on one instance) and can be switched off and on (scene/phantom.h).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "io/io_test_util.h"
#include "scene/animation.h"
#include "scene/phantom.h"
#include "scene/presets/dungeon_textures.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

// The tile under world point p.
std::pair<int, int> tileOf(const TileGrid& g, Vec3 p) {
    return {int(std::floor((p.x - g.origin.x) / g.tileSize)), int(std::floor((p.z - g.origin.z) / g.tileSize))};
}

const Mesh& meshNamed(const Scene& s, const std::string& name) {
    for (const Mesh& m : s.meshes)
        if (m.name == name) return m;
    throw std::runtime_error("no mesh " + name);
}

TEST(Dungeon, IsOneMapLitByGlowingTorchPanelsAndTheTorch) {
    const Scene s = makePreset("dungeon");
    s.validate();
    ASSERT_TRUE(s.tileGrid.has_value());
    EXPECT_EQ(s.tileGrid->width, 16);
    EXPECT_EQ(s.tileGrid->depth, 16);
    EXPECT_EQ(s.meshes.size(), 4u);  // floor, ceiling, walls, torch panels: built once, not per tile
    EXPECT_EQ(s.prototypes.size(), 1u);
    EXPECT_EQ(s.instances.size(), 1u);
    EXPECT_TRUE(s.lights.empty());  // the torches are panels, not point lights
    EXPECT_TRUE(s.torch.enabled);
    // Every torch panel glows from its front face into a tile one can stand on, on a wall.
    const Mesh& torches = meshNamed(s, "wall torches");
    ASSERT_GE(torches.triangleCount(), 16u);  // at least 8 panels of two triangles
    EXPECT_GT(maxComponent(s.materials[torches.material].emission), 1.0f);
    for (std::uint32_t t = 0; t < torches.triangleCount(); ++t) {
        const Vec3 a = torches.positions[torches.indices[3 * t]], b = torches.positions[torches.indices[3 * t + 1]],
                   c = torches.positions[torches.indices[3 * t + 2]];
        const Vec3 front = normalize(cross(b - a, c - a));
        const Vec3 centre = (a + b + c) * (1.0f / 3.0f);
        const auto [x, z] = tileOf(*s.tileGrid, centre + front * 0.5f);  // in front of it: the room
        EXPECT_TRUE(s.tileGrid->canStand(x, z)) << "panel triangle " << t;
        const auto [bx, bz] = tileOf(*s.tileGrid, centre - front * 0.5f);  // behind it: rock
        EXPECT_FALSE(s.tileGrid->canStand(bx, bz)) << "panel triangle " << t;
        EXPECT_NEAR(front.y, 0.0f, 1e-5f);
        EXPECT_GT(centre.y, 0.5f);
    }
    const auto [cx, cz] = tileOf(*s.tileGrid, s.camera.position);
    EXPECT_TRUE(s.tileGrid->canStand(cx, cz));
}

TEST(Dungeon, IsTexturedFromFreedoom) {
    PENUMBRA_REQUIRE_ASSET(freedoomWadPath());
    const Scene s = makePreset("dungeon");
    for (const char* name : {"floor", "ceiling", "walls"}) {
        const Mesh& m = meshNamed(s, name);
        EXPECT_EQ(m.uvs.size(), m.positions.size()) << name;
        const Material& mat = s.materials[m.material];
        ASSERT_TRUE(mat.albedoTexture.present()) << name;
        EXPECT_EQ(mat.albedoTexture.filter, Filter::Nearest) << name;
        const Texture& tex = s.textures[std::size_t(mat.albedoTexture.texture)];
        // A real picture, not a flat colour or the missing-texture checker's two colours.
        std::set<std::uint32_t> colours;
        for (std::size_t i = 0; i + 3 < tex.rgba.size(); i += 4)
            colours.insert(std::uint32_t(tex.rgba[i]) | std::uint32_t(tex.rgba[i + 1]) << 8 | std::uint32_t(tex.rgba[i + 2]) << 16);
        EXPECT_GT(colours.size(), 8u) << name << " (" << tex.name << ")";
    }
    // A wall texture of 128 texels covers 4 m: a 2 m wall tile spans half of it.
    const Mesh& walls = meshNamed(s, "walls");
    float uMin = 1e9f, uMax = -1e9f;
    for (std::size_t i = 0; i < 4; ++i) {
        uMin = std::min(uMin, walls.uvs[i].x);
        uMax = std::max(uMax, walls.uvs[i].x);
    }
    EXPECT_NEAR(uMax - uMin, 0.5f, 1e-4f);
}

TEST(Dungeon, IsFlatColouredWithANoteWithoutTheWad) {
    ::testing::internal::CaptureStderr();
    const Scene s = makeDungeon("/nonexistent/freedoom1.wad");
    const std::string err = ::testing::internal::GetCapturedStderr();
    s.validate();
    EXPECT_TRUE(s.textures.empty());
    for (const Material& m : s.materials) EXPECT_FALSE(m.albedoTexture.present()) << m.name;
    EXPECT_NE(err.find("penumbra: warning: the dungeon is flat-coloured"), std::string::npos) << err;
    EXPECT_NE(err.find("/nonexistent/freedoom1.wad is missing"), std::string::npos) << err;
    EXPECT_NE(err.find("freedoom"), std::string::npos) << err;
    EXPECT_EQ(s.meshes.size(), 4u);
}

TEST(Dungeon, ThePhantomPatrolsItsCorridor) {
    const Scene s = makePreset("dungeon");
    ASSERT_TRUE(animatesGeometry(s));
    int row = -1;
    float west = 1e9f, east = -1e9f;
    for (double t = 0; t < 40; t += 0.25) {
        const Scene at = sceneAtTime(s, t);
        const Vec3 p = at.instances[0].transform.point(Vec3{0});
        const auto [x, z] = tileOf(*s.tileGrid, p);
        ASSERT_TRUE(s.tileGrid->canStand(x, z)) << "t = " << t;
        if (row < 0) row = z;
        EXPECT_EQ(z, row) << "t = " << t;  // along one corridor
        west = std::min(west, p.x);
        east = std::max(east, p.x);
    }
    EXPECT_GT(east - west, 15.0f);  // and it walks its length, back and forth
}

TEST(Dungeon, ThePhantomSwitchesOffAndOn) {
    Scene s = makePreset("dungeon");
    const Scene untouched = s;
    PhantomSwitch phantom(s);
    ASSERT_TRUE(phantom.present());
    EXPECT_TRUE(phantom.shown());
    EXPECT_FALSE(phantom.set(s, true, 0.0));  // already shown: nothing changes
    applyInstanceAnimations(s, 3.0);
    // Off: parked under the level, far below every floor tile, shrunk, and no longer on the clock.
    ASSERT_TRUE(phantom.set(s, false, 3.0));
    EXPECT_FALSE(phantom.shown());
    const Affine parked = s.instances[0].transform;
    const Vec3 where = parked.point(Vec3{0});
    EXPECT_LT(where.y, -5.0f);
    EXPECT_LT(length(parked.vector(Vec3{1, 0, 0})), 0.01f);
    EXPECT_FALSE(animatesGeometry(s));
    for (double t : {3.5, 10.0, 40.0}) {
        applySceneTime(s, t);
        EXPECT_EQ(s.instances[0].transform.point(Vec3{0}), where) << "t = " << t;  // not moving
    }
    EXPECT_FALSE(phantom.set(s, false, 40.0));
    // On again: on its patrol, where the patrol is at that moment, and moving with the clock.
    ASSERT_TRUE(phantom.set(s, true, 40.0));
    EXPECT_TRUE(phantom.shown());
    const Scene expected = sceneAtTime(untouched, 40.0);
    EXPECT_EQ(s.instances[0].transform.point(Vec3{0}), expected.instances[0].transform.point(Vec3{0}));
    applyInstanceAnimations(s, 41.0);
    EXPECT_EQ(s.instances[0].transform.point(Vec3{0}), sceneAtTime(untouched, 41.0).instances[0].transform.point(Vec3{0}));
}

TEST(Dungeon, ScenesWithoutAPhantomIgnoreTheSwitch) {
    Scene s = makePreset("cornell");
    PhantomSwitch phantom(s);
    EXPECT_FALSE(phantom.present());
    EXPECT_FALSE(phantom.set(s, false, 0.0));
    EXPECT_TRUE(phantom.shown());
}

}  // namespace
}  // namespace penumbra
