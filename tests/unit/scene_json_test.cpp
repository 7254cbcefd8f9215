// JSON scene files: round trips, transforms, overrides and one-line errors that say where.
#include <gtest/gtest.h>

#include "scene_json_test_util.h"

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "scene/instances.h"
#include "scene/io/scene_json.h"
#include "scene/presets/presets.h"

namespace penumbra {
namespace {

Scene parse(const std::string& text, SceneFileSettings* settings = nullptr) { return test::parseSceneText(text, settings); }

std::string errorOf(const std::string& text) { return test::sceneTextError(text); }

TEST(SceneJson, ExportedPresetLoadsBackAsTheSameScene) {
    Scene cornell = makeCornellBox();
    Scene back = parse(sceneToJson(cornell));
    EXPECT_EQ(back.triangleCount(), cornell.triangleCount());
    EXPECT_EQ(back.materials.size(), cornell.materials.size());
    EXPECT_EQ(back.bounds().lo, cornell.bounds().lo);
    EXPECT_EQ(back.bounds().hi, cornell.bounds().hi);
    EXPECT_EQ(back.camera.position, cornell.camera.position);
    EXPECT_FLOAT_EQ(back.camera.fovYDegrees, cornell.camera.fovYDegrees);
    for (std::size_t i = 0; i < cornell.materials.size(); ++i) {
        EXPECT_EQ(back.materials[i].emission, cornell.materials[i].emission);
        EXPECT_EQ(back.materials[i].albedo, cornell.materials[i].albedo);
    }
}

TEST(SceneJson, AssetTransformsApplyScaleThenRotateThenTranslate) {
    Scene s = parse(R"({"assets": [{"preset": "furnace", "scale": 2, "rotate": [0, 0, 90], "translate": [10, 0, 0]}]})");
    // The furnace cube spans [-1, 1]^3: scaled to [-2, 2], rotated in place, moved to x = 10.
    EXPECT_NEAR(s.bounds().lo.x, 8.0f, 1e-4f);
    EXPECT_NEAR(s.bounds().hi.x, 12.0f, 1e-4f);
    EXPECT_NEAR(s.bounds().hi.y, 2.0f, 1e-4f);
}

TEST(SceneJson, MirroringKeepsFrontFacesPointingTheSameWay) {
    Scene plain = makeFurnace(0.5f, Vec3{1});
    Scene mirrored = parse(R"({"assets": [{"preset": "furnace", "scale": [-1, 1, 1]}]})");
    auto tris = flattenTriangles(mirrored);
    for (const SceneTriangle& t : tris) {
        Vec3 n = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        EXPECT_LT(dot(n, (t.p[0] + t.p[1] + t.p[2]) / 3.0f), 0.0f) << "a mirrored wall now faces outward";
    }
    EXPECT_EQ(tris.size(), plain.triangleCount());
}

TEST(SceneJson, MaterialOverridesChangeOnlyTheGivenFields) {
    Scene s = parse(R"({"assets": [{"preset": "cornell"}], "materials": [{"name": "red", "albedo": [0.1, 0.2, 0.3]}]})");
    for (const Material& m : s.materials)
        if (m.name == "red") {
            EXPECT_EQ(m.albedo, (Vec3{0.1f, 0.2f, 0.3f}));
            EXPECT_EQ(m.emission, Vec3{0});
        }
}

TEST(SceneJson, MaterialKeysForSpecularAndAbsorptionAreRead) {
    Scene s = parse(R"({"assets": [{"preset": "cornell"}], "materials": [{"name": "red", "specular": 0.5,
        "absorptionColor": [0.9, 0.5, 0.1], "absorptionDistance": 0.05}]})");
    bool found = false;
    for (const Material& m : s.materials)
        if (m.name == "red") {
            found = true;
            EXPECT_FLOAT_EQ(m.specular, 0.5f);
            EXPECT_EQ(m.absorptionColor, (Vec3{0.9f, 0.5f, 0.1f}));
            EXPECT_FLOAT_EQ(m.absorptionDistance, 0.05f);
        }
    EXPECT_TRUE(found);
    EXPECT_NE(errorOf(R"({"materials": [{"name": "x", "absorptionDistance": -1}]})"), "");
    EXPECT_NE(errorOf(R"({"materials": [{"name": "x", "specular": 2}]})"), "");
}

TEST(SceneJson, AnAssetMaterialReplacesEveryMaterialOfTheAsset) {
    Scene s = parse(R"({"assets": [{"preset": "cornell"}, {"preset": "caffeine", "scale": 0.1, "material": "gold"}],
                       "materials": [{"name": "gold", "metallic": 1, "albedo": [1, 0.8, 0.3]}]})");
    const Scene cornell = makeCornellBox(), caffeine = makePreset("caffeine");
    ASSERT_EQ(s.meshes.size(), cornell.meshes.size() + caffeine.meshes.size());
    ASSERT_EQ(s.spheres.size(), caffeine.spheres.size());
    ASSERT_FALSE(caffeine.spheres.empty());
    const std::string& gold = s.materials.back().name;
    ASSERT_EQ(gold, "gold");
    for (std::size_t m = 0; m < s.meshes.size(); ++m)
        EXPECT_EQ(s.materials[s.meshes[m].material].name == gold, m >= cornell.meshes.size()) << "mesh " << m;
    for (const Sphere& sphere : s.spheres) EXPECT_EQ(s.materials[sphere.material].name, gold);
}

TEST(SceneJson, AnAssetMaterialMustExist) {
    const std::string e = errorOf(R"({"assets": [{"preset": "cornell"}, {"preset": "furnace", "material": "nope"}]})");
    EXPECT_NE(e.find("assets[1].material: no material named 'nope'"), std::string::npos) << e;
    EXPECT_NE(errorOf(R"({"assets": [{"preset": "cornell", "material": 3}]})").find("assets[0].material"), std::string::npos);
}

TEST(SceneJson, AMaterialNothingUsesIsAWarning) {
    testing::internal::CaptureStderr();
    parse(R"({"assets": [{"preset": "cornell"}], "materials": [{"name": "unused", "albedo": [1, 0, 0]}, {"name": "red"}]})");
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("penumbra: warning: test.json: materials[0] ('unused') is not used"), std::string::npos) << err;
    EXPECT_EQ(err.find("materials[1]"), std::string::npos) << "'red' is the Cornell box's: " << err;

    testing::internal::CaptureStderr();
    parse(R"({"assets": [{"preset": "cornell", "material": "used"}],
              "materials": [{"name": "used"}, {"name": "sphere"}, {"name": "quad"}],
              "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "sphere"}],
              "quads": [{"material": "quad", "corners": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]}]})");
    err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err.find("warning"), std::string::npos) << err;
}

// Including a scene file with a transform moves its whole world: geometry, spheres, lights and
// (as the first asset) its camera, whose lens scales with it.
TEST(SceneJson, IncludingASceneFileTransformsItsWholeWorld) {
    const auto dir = std::filesystem::temp_directory_path() / ("penumbra-world-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "inner.json") << R"({
        "materials": [{"name": "m"}],
        "quads": [{"material": "m", "corners": [[0, 0, 0], [1, 0, 0], [1, 0, -1], [0, 0, -1]]}],
        "spheres": [{"center": [1, 2, 3], "radius": 0.5, "material": "m"}],
        "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "radius": 0.1}],
        "camera": {"position": [0, 1, 4], "look_at": [0, 1, 0], "aperture": 0.02, "focus_distance": 4}})";
    std::ofstream(dir / "outer.json")
        << R"({"assets": [{"file": "inner.json", "scale": 2, "rotate": [0, 0, 90], "translate": [10, 0, 0]}]})";
    const Scene s = loadSceneJson(dir / "outer.json");
    std::filesystem::remove_all(dir);
    const auto near = [](Vec3 a, Vec3 b) { return length(a - b) < 1e-4f; };
    // Scale 2, then 90 degrees about z (x -> y, y -> -x), then x + 10.
    EXPECT_TRUE(near(s.spheres.at(0).center, {6, 2, 6}));
    EXPECT_FLOAT_EQ(s.spheres[0].radius, 1.0f);
    EXPECT_TRUE(near(s.lights.at(0).position, {4, 0, 0}));
    EXPECT_TRUE(near(s.lights[0].direction, {1, 0, 0}));
    EXPECT_FLOAT_EQ(s.lights[0].radius, 0.2f);
    EXPECT_TRUE(near(s.camera.position, {8, 0, 8}));
    EXPECT_TRUE(near(s.camera.lookAt, {8, 0, 0}));
    EXPECT_TRUE(near(s.camera.up, {-1, 0, 0}));
    EXPECT_FLOAT_EQ(s.camera.apertureRadius, 0.04f);
    EXPECT_FLOAT_EQ(s.camera.focusDistance, 8.0f);
}

TEST(SceneJson, RenderSettingsAreRead) {
    SceneFileSettings settings;
    parse(R"({"assets": [{"preset": "cornell"}], "render": {"spp": 7, "bounces": 3, "width": 20, "height": 10, "exposure": 1.5}})",
          &settings);
    EXPECT_EQ(settings.samplesPerPixel, 7u);
    EXPECT_EQ(settings.maxBounces, 3u);
    EXPECT_EQ(settings.width, 20u);
    EXPECT_EQ(settings.height, 10u);
    EXPECT_FLOAT_EQ(*settings.exposure, 1.5f);
}

TEST(SceneJson, ErrorsNameTheFileAndThePlace) {
    EXPECT_NE(errorOf("{").find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf(R"({"assets": [{"preset": "cornell"}], "render": {"spp": 0}})").find("render.spp"), std::string::npos);
    EXPECT_NE(errorOf(R"({"materials": [{"name": "m"}], "meshes": [{"material": "nope", "positions": [], "indices": []}]})")
                  .find("no material named 'nope'"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"materials": [{"name": "m"}], "meshes": [{"material": "m", "positions": [0,0,0], "indices": [0,0,5]}]})")
                  .find("meshes[0].indices[2]"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"assets": [{"preset": "cornell"}], "materials": [{"name": "red", "albedo": [2, 0, 0]}]})")
                  .find("materials[0].albedo[0]"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"assets": [{"file": "does-not-exist.obj"}]})").find("does-not-exist.obj"), std::string::npos);
    EXPECT_NE(errorOf(R"({})").find("no geometry"), std::string::npos);
    for (const std::string& e : {errorOf("{"), errorOf(R"({"camera": 5, "assets": [{"preset": "cornell"}]})")})
        EXPECT_EQ(e.rfind("test.json: ", 0), 0u) << e;
}

TEST(SceneJson, AFileThatIncludesItselfIsAnErrorNotAHang) {
    auto path = std::filesystem::temp_directory_path() / ("penumbra-self-" + std::to_string(::getpid()) + ".json");
    std::ofstream(path) << R"({"assets": [{"file": ")" << path.filename().string() << R"("}]})";
    try {
        loadSceneJson(path);
        FAIL() << "a self-including scene loaded";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("nest"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace penumbra

namespace penumbra::test {
namespace {

// Inline faces whose arithmetic overflows floats are dropped and said to be; with nothing left,
// the file is refused in one line rather than rendered black.
TEST(SceneJson, FacesThatOverflowAreSkippedAndNoneLeftIsAnError) {
    const std::string big = R"({"materials":[{"name":"m"}],"meshes":[{"name":"big","material":"m",)"
                            R"("positions":[0,0,0,1e30,0,0,0,1e30,0],"indices":[0,1,2]})";
    const std::string good = R"({"name":"good","material":"m","positions":[0,0,0,1,0,0,0,1,0],"indices":[0,1,2]})";
    testing::internal::CaptureStderr();
    const Scene s = parseSceneText(big + "," + good + "]}");
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.triangleCount(), 1u);
    EXPECT_NE(warning.find("test.json: skipped 1 face with coordinates that are not finite"), std::string::npos)
        << warning;
    const std::string e = sceneTextError(big + "]}");
    EXPECT_NE(e.find("test.json: no face can be rendered"), std::string::npos) << e;
}

}  // namespace
}  // namespace penumbra::test

namespace penumbra {
namespace {

// A scene file placing an asset twice through "instances": one prototype, two instances, the
// asset's own transform first; baked, the same meshes as two separately placed assets.
TEST(SceneJson, InstancesPlaceOneMeshManyTimes) {
    const auto dir = std::filesystem::temp_directory_path() / ("penumbra-instances-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "tile.json") << R"({
        "materials": [{"name": "m"}],
        "quads": [{"material": "m", "corners": [[0, 0, 0], [1, 0, 0], [1, 0, -1], [0, 0, -1]]}]})";
    std::ofstream(dir / "instanced.json") << R"({"assets": [{"file": "tile.json", "scale": 2, "material": "red",
        "instances": [{"translate": [10, 0, 0]}, {"rotate": [0, 90, 0], "translate": [0, 0, 5]}]}],
        "materials": [{"name": "red", "albedo": [0.8, 0.1, 0.1]}]})";
    std::ofstream(dir / "copies.json") << R"({"assets": [
        {"file": "tile.json", "scale": 2, "translate": [10, 0, 0], "material": "red"},
        {"file": "tile.json", "scale": 2, "rotate": [0, 90, 0], "translate": [0, 0, 5], "material": "red"}],
        "materials": [{"name": "red", "albedo": [0.8, 0.1, 0.1]}]})";
    std::ofstream(dir / "bad.json") << R"({"assets": [{"file": "tile.json", "instances": []}]})";
    const Scene s = loadSceneJson(dir / "instanced.json");
    const Scene copies = loadSceneJson(dir / "copies.json");
    std::string badError;
    try {
        loadSceneJson(dir / "bad.json");
    } catch (const Error& e) {
        badError = e.what();
    }
    std::filesystem::remove_all(dir);
    EXPECT_TRUE(s.meshes.empty());
    ASSERT_EQ(s.prototypes.size(), 1u);
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.materials[s.prototypes[0].meshes.at(0).material].name, "red");
    Scene baked = s;
    bakeAllInstances(baked);
    ASSERT_EQ(baked.meshes.size(), copies.meshes.size());
    for (std::size_t m = 0; m < copies.meshes.size(); ++m)
        for (std::size_t v = 0; v < copies.meshes[m].positions.size(); ++v)
            EXPECT_LT(length(baked.meshes[m].positions[v] - copies.meshes[m].positions[v]), 1e-5f);
    // Instance bounds (transformBounds) are padded outwards by a few ulps of the terms summed.
    EXPECT_LT(length(s.bounds().hi - copies.bounds().hi), 1e-4f);
    EXPECT_GE(s.bounds().hi.x, copies.bounds().hi.x);
    EXPECT_NE(badError.find("instances"), std::string::npos) << badError;
}

}  // namespace
}  // namespace penumbra
