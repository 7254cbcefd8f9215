// The bvh-lesson preset: what its doc comment promises is what it contains.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace penumbra
