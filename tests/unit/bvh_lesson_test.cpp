// The bvh-lesson preset: what its doc comment promises is what it contains.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene/presets/presets.h"

namespace penumbra {
namespace {

const Mesh& meshNamed(const Scene& s, const std::string& name) {
    for (const Mesh& m : s.meshes)
        if (m.name == name) return m;
    throw std::runtime_error("no mesh " + name);
}

Aabb meshBounds(const Mesh& m) {
    Aabb b;
    for (Vec3 p : m.positions) b.grow(p);
    return b;
}

TEST(BvhLesson, IsAValidRoomWithSeparateCubesAClusterAndADiagonalSlab) {
    Scene s = makePreset("bvh-lesson");
    s.validate();
    EXPECT_EQ(meshNamed(s, "separate cubes").triangleCount(), 5u * 12u);
    EXPECT_EQ(meshNamed(s, "cluster").triangleCount(), 108u * 12u);
    // The cubes stay on their sides of the room, and the slab spans it diagonally.
    EXPECT_LT(meshBounds(meshNamed(s, "separate cubes")).hi.x, 0.0f);
    EXPECT_GT(meshBounds(meshNamed(s, "cluster")).lo.x, 0.0f);
    Aabb slab = meshBounds(meshNamed(s, "diagonal slab"));
    EXPECT_GT(slab.extent().x, 5.0f);
    EXPECT_GT(slab.extent().z, 5.0f);
    // Its bounds are mostly empty: the slab's volume is under 5% of its box's.
    const float volume = 8.0f * 1.2f * 0.15f;
    EXPECT_LT(volume, 0.05f * slab.extent().x * slab.extent().y * slab.extent().z);
    // A light, so the default render is not black.
    bool emissive = false;
    for (const Material& m : s.materials) emissive |= m.isEmissive();
    EXPECT_TRUE(emissive);
}

// `outer` holds `inner` with room to spare on every side.
bool strictlyInside(const Aabb& inner, const Aabb& outer) {
    for (int k = 0; k < 3; ++k)
        if (!(inner.lo[k] > outer.lo[k] && inner.hi[k] < outer.hi[k])) return false;
    return true;
}

bool overlap(const Aabb& a, const Aabb& b) {
    for (int k = 0; k < 3; ++k)
        if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
}

TEST(BvhLesson, HasTheWebGpuLessonsNestedBoxesAndFloorGrid) {
    const Scene s = makePreset("bvh-lesson");
    const Mesh& outer = meshNamed(s, "nested box outer");
    const Mesh& middle = meshNamed(s, "nested box middle");
    const Mesh& inner = meshNamed(s, "nested box inner");
    // Two open boxes (five faces) and a closed cube, each box inside the one around it.
    EXPECT_EQ(outer.triangleCount(), 10u);
    EXPECT_EQ(middle.triangleCount(), 10u);
    EXPECT_EQ(inner.triangleCount(), 12u);
    EXPECT_TRUE(strictlyInside(meshBounds(middle), meshBounds(outer)));
    EXPECT_TRUE(strictlyInside(meshBounds(inner), meshBounds(middle)));
    // The open side faces the camera, so one can look in: no outer-box vertex lies on its -z
    // side, and the camera stands beyond it.
    const Aabb out = meshBounds(outer);
    EXPECT_LT(s.camera.position.z, out.lo.z);
    for (std::uint32_t t = 0; t < outer.triangleCount(); ++t) {
        float zMax = -1e9f;
        for (int c = 0; c < 3; ++c) zMax = std::max(zMax, outer.positions[outer.indices[3 * t + c]].z);
        EXPECT_GT(zMax, out.lo.z + 1e-4f) << "triangle " << t << " closes the -z side";
    }
    // They stand clear of the other objects.
    for (const char* other : {"separate cubes", "cluster", "floor grid light", "floor grid dark"})
        EXPECT_FALSE(overlap(out, meshBounds(meshNamed(s, other)))) << other;

    // The floor grid: a 4 x 4 checkerboard, light and dark squares at two heights just above the floor.
    const Mesh& light = meshNamed(s, "floor grid light");
    const Mesh& dark = meshNamed(s, "floor grid dark");
    EXPECT_EQ(light.triangleCount(), 8u * 2u);
    EXPECT_EQ(dark.triangleCount(), 8u * 2u);
    const Aabb l = meshBounds(light), d = meshBounds(dark);
    EXPECT_EQ(l.lo.y, l.hi.y);
    EXPECT_EQ(d.lo.y, d.hi.y);
    EXPECT_NE(l.lo.y, d.lo.y);
    EXPECT_GT(std::min(l.lo.y, d.lo.y), 0.0f);
    EXPECT_LT(std::max(l.hi.y, d.hi.y), 0.05f);
    for (const char* other : {"separate cubes", "cluster"}) {
        EXPECT_FALSE(overlap(l, meshBounds(meshNamed(s, other)))) << other;
        EXPECT_FALSE(overlap(d, meshBounds(meshNamed(s, other)))) << other;
    }
    // Everything is inside the room.
    const Aabb room = meshBounds(meshNamed(s, "room"));
    for (const Mesh& m : s.meshes)
        for (Vec3 p : m.positions)
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(p[k], room.lo[k]) << m.name;
                EXPECT_LE(p[k], room.hi[k]) << m.name;
            }
    s.validate();
}

}  // namespace
}  // namespace penumbra
