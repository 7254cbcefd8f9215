#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

TEST(Scene, CornellBoxMatchesThePublishedGeometry) {
    Scene s = makeCornellBox();
    EXPECT_NO_THROW(s.validate());
    // 5 walls + light = 6 quads, two blocks of 5 quads each: 16 quads.
    EXPECT_EQ(s.triangleCount(), 32u);
    Aabb b = s.bounds();
    EXPECT_NEAR(b.hi.x, 0.556f, 1e-6f);
    EXPECT_NEAR(b.hi.y, 0.5488f, 1e-6f);
    EXPECT_NEAR(b.hi.z, 0.5592f, 1e-6f);
    EXPECT_NEAR(b.lo.x, 0.0f, 1e-6f);
    // The light faces down into the room, and is 130 x 105 mm.
    for (const Mesh& m : s.meshes) {
        if (m.name != "light") continue;
        Scene lightOnly = s;
        lightOnly.meshes = {m};
        auto tris = flattenTriangles(lightOnly);
        double area = 0;
        for (const SceneTriangle& t : tris) {
            Vec3 n = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
            EXPECT_LT(n.y, 0.0f);
            area += 0.5 * length(n);
        }
        EXPECT_NEAR(area, 0.130 * 0.105, 1e-6);
    }
}

TEST(Scene, FurnaceWallsAllFaceInward) {
    Scene s = makeFurnace(0.5f, Vec3{1});
    for (const SceneTriangle& t : flattenTriangles(s)) {
        Vec3 n = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        Vec3 centre = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        EXPECT_LT(dot(n, centre), 0.0f) << "a wall faces out of the box";
    }
    EXPECT_EQ(s.triangleCount(), 12u);
}

TEST(Scene, ValidateNamesTheProblem) {
    Scene s = makeFurnace(0.5f, Vec3{1});
    s.meshes[0].indices.push_back(99);
    s.meshes[0].indices.push_back(0);
    s.meshes[0].indices.push_back(1);
    try {
        s.validate();
        FAIL() << "an out-of-range index was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("index 99"), std::string::npos) << e.what();
    }
    Scene nan = makeFurnace(0.5f, Vec3{1});
    nan.meshes[0].positions[0].x = std::nanf("");
    EXPECT_THROW(nan.validate(), Error);
    Scene bright = makeFurnace(1.5f, Vec3{1});
    EXPECT_THROW(bright.validate(), Error);
}

TEST(Scene, BadCamerasAreRejected) {
    Camera c;
    c.lookAt = c.position;
    EXPECT_THROW(validateCamera(c), UsageError);
    c = Camera{};
    c.up = c.lookAt - c.position;
    EXPECT_THROW(validateCamera(c), UsageError);
    c = Camera{};
    c.fovYDegrees = 180;
    EXPECT_THROW(validateCamera(c), UsageError);
    EXPECT_NO_THROW(validateCamera(Camera{}));
}

TEST(Scene, UnknownPresetListsTheKnownOnes) {
    try {
        makePreset("nope");
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("cornell"), std::string::npos);
    }
}

TEST(Scene, FlattenFallsBackToTheFaceNormalForBrokenNormals) {
    Scene s = makeFurnace(0.5f, Vec3{1});
    s.meshes[0].normals.assign(s.meshes[0].positions.size(), Vec3{0, 0, 0});
    for (const SceneTriangle& t : flattenTriangles(s)) {
        Vec3 face = normalize(cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
        for (Vec3 n : t.n) EXPECT_NEAR(dot(n, face), 1.0f, 1e-5f);
    }
}

}  // namespace
}  // namespace penumbra
