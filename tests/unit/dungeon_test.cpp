// The dungeon preset: one map, no per-tile copies, torches on walls, and a phantom that patrols
// its corridor on walkable tiles (a scene motion on one instance).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/animation.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

// The tile under world point p.
std::pair<int, int> tileOf(const TileGrid& g, Vec3 p) {
    return {int(std::floor((p.x - g.origin.x) / g.tileSize)), int(std::floor((p.z - g.origin.z) / g.tileSize))};
}

TEST(Dungeon, IsOneMapLitByWallTorchesAndTheTorch) {
    const Scene s = makePreset("dungeon");
    s.validate();
    ASSERT_TRUE(s.tileGrid.has_value());
    EXPECT_EQ(s.tileGrid->width, 16);
    EXPECT_EQ(s.tileGrid->depth, 16);
    EXPECT_EQ(s.meshes.size(), 3u);  // floor, ceiling, walls: built once, not per tile
    EXPECT_EQ(s.prototypes.size(), 1u);
    EXPECT_EQ(s.instances.size(), 1u);
    EXPECT_GE(s.lights.size(), 8u);
    EXPECT_TRUE(s.torch.enabled);
    // Every wall torch hangs inside the map, above a tile one can stand on.
    for (const Light& l : s.lights) {
        const auto [x, z] = tileOf(*s.tileGrid, l.position);
        EXPECT_TRUE(s.tileGrid->canStand(x, z)) << l.name << " at tile " << x << "," << z;
        EXPECT_GT(l.position.y, 1.0f);
    }
    const auto [cx, cz] = tileOf(*s.tileGrid, s.camera.position);
    EXPECT_TRUE(s.tileGrid->canStand(cx, cz));
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

}  // namespace
}  // namespace penumbra
