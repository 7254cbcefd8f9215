// The built-in scenes: each one is valid, lit, and built the way its comment says.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "core/error.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

bool hasLight(const Scene& s) {
    for (const Material& m : s.materials)
        if (m.isEmissive()) return true;
    return !s.lights.empty() || s.environment.map.has_value() || maxComponent(s.background) > 0;
}

TEST(Presets, EveryPresetIsValidAndLit) {
    for (const std::string& name : presetNames()) {
        if (name == "suzanne" && !std::filesystem::exists(suzanneModelPath())) continue;  // its own test says why
        Scene s = makePreset(name);
        EXPECT_NO_THROW(s.validate()) << name;
        EXPECT_GT(s.triangleCount() + s.spheres.size(), 0u) << name;
        EXPECT_TRUE(hasLight(s)) << name;
    }
    EXPECT_THROW(makePreset("no-such-scene"), UsageError);
}

const Material& materialNamed(const Scene& s, const std::string& name) {
    for (const Material& m : s.materials)
        if (m.name == name) return m;
    throw Error("no material " + name);
}

TEST(Presets, BunnyRoomHasMirrorsGlassAndABunnyStandingOnTheFloor) {
    Scene s = makePreset("bunny-room");
    EXPECT_EQ(materialNamed(s, "mirror").metallic, 1.0f);
    EXPECT_EQ(materialNamed(s, "mirror").roughness, 0.0f);
    EXPECT_EQ(materialNamed(s, "glass").transmission, 1.0f);
    EXPECT_GT(materialNamed(s, "semi-specular floor").specular, 0.0f);
    ASSERT_EQ(s.spheres.size(), 1u);  // the glass sphere (the bulbs are lights with a radius)
    EXPECT_EQ(s.lights.size(), 2u);
    for (const Light& l : s.lights) EXPECT_GT(l.radius, 0.0f);
    // The bunny (or its stand-in) is the last mesh: 0.75 m tall, feet on the floor.
    const Mesh& bunny = s.meshes.back();
    float lo = 1e9f, hi = -1e9f;
    for (Vec3 p : bunny.positions) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    EXPECT_NEAR(lo, 0.0f, 1e-4f);
    EXPECT_NEAR(hi - lo, 0.75f, 1e-3f);
    if (std::filesystem::exists("/usr/share/glmark2/models/bunny.obj"))
        EXPECT_EQ(bunny.triangleCount(), 69666u);
    else
        EXPECT_EQ(bunny.triangleCount(), 20u);
}

TEST(Presets, SuzanneSitsInTheMiddleOfTheCornellRoomFacingTheCamera) {
    if (!std::filesystem::exists(suzanneModelPath())) {
        EXPECT_THROW(makePreset("suzanne"), Error);  // one clear line naming the package, no crash
        if (std::getenv("CI")) FAIL() << "missing test asset " << suzanneModelPath();
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    Scene s = makePreset("suzanne");
    EXPECT_NO_THROW(s.validate());
    for (const Mesh& m : s.meshes) EXPECT_TRUE(m.name != "short block" && m.name != "tall block") << m.name;
    const Mesh& head = s.meshes.back();
    EXPECT_EQ(head.triangleCount(), 3872u);  // Suzanne_248.blend: the monkey subdivided once
    EXPECT_EQ(s.materials[head.material].name, "suzanne");
    Aabb box;
    for (Vec3 p : head.positions) box.grow(p);
    EXPECT_NEAR(box.extent().x, 0.30f, 1e-3f);  // ear to ear
    EXPECT_NEAR(box.center().x, 0.278f, 1e-3f);
    EXPECT_NEAR(box.center().z, 0.28f, 1e-3f);
    EXPECT_GT(box.lo.y, 0.0f);  // floating: clear of the floor and the ceiling
    EXPECT_LT(box.hi.y, 0.5488f);
    // Facing the camera (at -z): the face (eyes, brow, mouth) holds most of the vertices, so
    // their centroid lies on the camera's side of the box's centre; turned away, it would not.
    Vec3 mean{0};
    for (Vec3 p : head.positions) mean += p;
    mean = mean / float(head.positions.size());
    EXPECT_LT(mean.z, box.center().z - 0.01f);
    // Upright: the ears droop, so their tips (the widest vertices) lie below the middle.
    Vec3 widest = head.positions.front();
    for (Vec3 p : head.positions)
        if (std::abs(p.x - box.center().x) > std::abs(widest.x - box.center().x)) widest = p;
    EXPECT_LT(widest.y, box.center().y - 0.02f);
}

TEST(Presets, MaterialSweepRowsChangeOneParameterEach) {
    Scene s = makePreset("materials");
    ASSERT_EQ(s.spheres.size(), 17u);
    // Spheres are pushed front, middle, back for each column, left to right.
    for (int i = 0; i + 1 < 5; ++i) {
        const Material& plastic = s.materials[s.spheres[3 * i].material];
        const Material& nextPlastic = s.materials[s.spheres[3 * (i + 1)].material];
        EXPECT_LT(plastic.roughness, nextPlastic.roughness);
        EXPECT_EQ(plastic.metallic, 0.0f);
        const Material& gold = s.materials[s.spheres[3 * i + 1].material];
        EXPECT_LT(gold.roughness, s.materials[s.spheres[3 * (i + 1) + 1].material].roughness);
        EXPECT_EQ(gold.metallic, 1.0f);
        const Material& metal = s.materials[s.spheres[3 * i + 2].material];
        EXPECT_LT(metal.metallic, s.materials[s.spheres[3 * (i + 1) + 2].material].metallic);
        EXPECT_EQ(metal.roughness, 0.3f);
    }
    EXPECT_TRUE(s.environment.map.has_value());
    ASSERT_TRUE(s.environment.sun.has_value());
    EXPECT_GT(s.environment.sun->angularRadius, 0.0f);
}

}  // namespace
}  // namespace penumbra
