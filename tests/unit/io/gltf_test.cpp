// glTF importer: node transforms, primitives, materials and textures, lights, cameras, and
// hostile or broken files (Debian's assimp test models included).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "../image/test_dir.h"
#include "../smooth_sphere.h"
#include "core/error.h"
#include "io_test_util.h"
#include "mesh_files.h"
#include "scene/animation.h"
#include "scene/instances.h"
#include "scene/io/gltf.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

using test::dataDir;
const std::filesystem::path kAssimp = "/usr/share/assimp/models/glTF2";

std::string errorOf(auto&& fn) {
    testing::internal::CaptureStderr();
    std::string what = "<no error>";
    try {
        fn();
    } catch (const Error& e) {
        what = e.what();
    }
    testing::internal::GetCapturedStderr();
    return what;
}

void expectNear(Vec3 a, Vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

const Mesh* meshNamed(const Scene& s, const std::string& name) {
    for (const Mesh& m : s.meshes)
        if (m.name == name) return &m;
    return nullptr;
}

class GltfScene : public testing::Test {
protected:
    static void SetUpTestSuite() {
        testing::internal::CaptureStderr();
        scene_ = new Scene(loadGltf(dataDir() / "gltf/scene.gltf"));
        warnings_ = new std::string(testing::internal::GetCapturedStderr());
    }
    static void TearDownTestSuite() {
        delete scene_;
        delete warnings_;
    }
    static Scene* scene_;
    static std::string* warnings_;
};
Scene* GltfScene::scene_ = nullptr;
std::string* GltfScene::warnings_ = nullptr;

TEST_F(GltfScene, ParentTranslateThenChildRotate) {
    const Mesh* tri = meshNamed(*scene_, "tri/0");
    ASSERT_NE(tri, nullptr);
    ASSERT_EQ(tri->positions.size(), 3u);  // non-indexed primitive
    EXPECT_EQ(tri->indices, (std::vector<std::uint32_t>{0, 1, 2}));
    // world = T(10,0,0) * Rz(90): (1,0,0) -> (0,1,0) -> (10,1,0).
    expectNear(tri->positions[0], {10, 0, 0});
    expectNear(tri->positions[1], {10, 1, 0});
    expectNear(tri->positions[2], {9, 0, 0});
}

TEST_F(GltfScene, NonTriangleModesAreSkippedWithWarning) {
    EXPECT_EQ(scene_->triangleCount(), 3u);  // 1 + quad, the LINES primitive is gone
    EXPECT_NE(warnings_->find("mode 1"), std::string::npos) << *warnings_;
}

TEST_F(GltfScene, MirroredNodeFlipsWindingAndKeepsNormals) {
    const Mesh* quad = meshNamed(*scene_, "quad/0");
    ASSERT_NE(quad, nullptr);
    ASSERT_EQ(quad->triangleCount(), 2u);
    Vec3 p0 = quad->positions[quad->indices[0]], p1 = quad->positions[quad->indices[1]],
         p2 = quad->positions[quad->indices[2]];
    Vec3 geometric = normalize(cross(p1 - p0, p2 - p0));
    expectNear(geometric, {0, 0, 1});
    expectNear(quad->normals[0], {0, 0, 1});
    expectNear(quad->positions[1], {-1, 0, -3});
    ASSERT_EQ(quad->uvs.size(), 4u);
    EXPECT_FLOAT_EQ(quad->uvs[2].x, 1.0f);
}

// A node's rotation (quaternion), mirroring non-uniform scale and translation: positions go by
// T R S, normals by the inverse transpose R S^-1 (written out here from the quaternion), and the
// winding is reversed so that front faces stay outside.
TEST(GltfLoader, NodeTransformsTurnNormalsByTheInverseTranspose) {
    const Vec3 axis = normalize(Vec3{1, 2, 3}), scale{0.5f, -2.0f, 1.5f}, translation{1, -2, 3};
    const float half = degreesToRadians(0.5f * 70.0f);
    const float x = axis.x * std::sin(half), y = axis.y * std::sin(half), z = axis.z * std::sin(half),
                w = std::cos(half);
    const Vec3 r0{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)};
    const Vec3 r1{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)};
    const Vec3 r2{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    const auto rotate = [&](Vec3 v) { return Vec3{dot(r0, v), dot(r1, v), dot(r2, v)}; };

    const Mesh sphere = test::smoothSphere(Vec3{0}, 1.0f, 4, 6, 0);
    test::TempDir dir;
    const nlohmann::json node = {{"rotation", {x, y, z, w}},
                                 {"scale", {scale.x, scale.y, scale.z}},
                                 {"translation", {translation.x, translation.y, translation.z}}};
    test::writeGltf(dir.path(), "sphere", sphere, node);
    const Scene s = loadGltf(dir / "sphere.gltf");
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.positions.size(), sphere.positions.size());
    ASSERT_EQ(m.normals.size(), sphere.normals.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        expectNear(m.positions[i], translation + rotate(sphere.positions[i] * scale), 1e-5f);
        expectNear(m.normals[i], normalize(rotate(sphere.normals[i] / scale)), 1e-5f);
    }
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        EXPECT_EQ(m.indices[t], sphere.indices[t]);
        EXPECT_EQ(m.indices[t + 1], sphere.indices[t + 2]) << "a mirroring node keeps the winding";
    }
}

// Two nodes that use one mesh: the mesh is stored once (a prototype in its own space) and placed
// twice; baked, the instances are the meshes the nodes' transforms make.
TEST(GltfLoader, NodesSharingAMeshBecomeInstances) {
    const Mesh sphere = test::smoothSphere(Vec3{0}, 1.0f, 4, 6, 0);
    test::TempDir dir;
    test::writeGltf(dir.path(), "sphere", sphere, nlohmann::json{{"translation", {1, 0, 0}}});
    nlohmann::json doc;
    std::ifstream(dir / "sphere.gltf") >> doc;
    doc["nodes"].push_back({{"mesh", 0}, {"translation", {0, 2, 0}}, {"scale", {2, 2, -2}}});
    doc["scenes"][0]["nodes"].push_back(1);
    std::ofstream(dir / "two.gltf") << doc.dump();
    Scene s = loadGltf(dir / "two.gltf");
    EXPECT_TRUE(s.meshes.empty());
    ASSERT_EQ(s.prototypes.size(), 1u);
    ASSERT_EQ(s.instances.size(), 2u);
    ASSERT_EQ(s.prototypes[0].meshes.size(), 1u);
    EXPECT_EQ(s.prototypes[0].meshes[0].positions.size(), sphere.positions.size());
    bakeAllInstances(s);
    ASSERT_EQ(s.meshes.size(), 2u);
    for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
        expectNear(s.meshes[0].positions[i], sphere.positions[i] + Vec3{1, 0, 0}, 1e-5f);
        expectNear(s.meshes[1].positions[i], sphere.positions[i] * Vec3{2, 2, -2} + Vec3{0, 2, 0}, 1e-5f);
    }
    EXPECT_EQ(s.meshes[1].indices[1], sphere.indices[2]) << "a mirroring node keeps the winding";
}

// A node with a keyframed translation under a fixed parent: at each moment the instance is where
// the keys say (linear, step and cubic-spline interpolation), before the first key at the first.
Vec3 animatedPosition(const std::string& interpolation, const std::vector<float>& values, double seconds) {
    const Mesh sphere = test::smoothSphere(Vec3{0}, 1.0f, 4, 6, 0);
    test::TempDir dir;
    test::writeGltf(dir.path(), "sphere", sphere);
    const std::vector<float> times = {0.0f, 1.0f, 2.0f};
    {
        std::ofstream bin(dir / "anim.bin", std::ios::binary);
        bin.write(reinterpret_cast<const char*>(times.data()), std::streamsize(times.size() * 4));
        bin.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * 4));
    }
    nlohmann::json doc;
    std::ifstream(dir / "sphere.gltf") >> doc;
    const int buffer = int(doc["buffers"].size()), view = int(doc["bufferViews"].size()), acc = int(doc["accessors"].size());
    doc["buffers"].push_back({{"uri", "anim.bin"}, {"byteLength", (times.size() + values.size()) * 4}});
    doc["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 0}, {"byteLength", times.size() * 4}});
    doc["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", times.size() * 4}, {"byteLength", values.size() * 4}});
    doc["accessors"].push_back({{"bufferView", view}, {"componentType", 5126}, {"count", times.size()}, {"type", "SCALAR"},
                                {"min", {0.0}}, {"max", {2.0}}});
    doc["accessors"].push_back({{"bufferView", view + 1}, {"componentType", 5126}, {"count", values.size() / 3}, {"type", "VEC3"}});
    using Json = nlohmann::json;
    doc["nodes"].push_back({{"children", Json::array({0})}, {"translation", {0, 0, 5}}});
    doc["scenes"][0]["nodes"] = Json::array({1});
    const Json sampler = {{"input", acc}, {"output", acc + 1}, {"interpolation", interpolation}};
    const Json channel = {{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}};
    doc["animations"] = Json::array({Json{{"samplers", Json::array({sampler})}, {"channels", Json::array({channel})}}});
    std::ofstream(dir / "animated.gltf") << doc.dump();
    Scene s = loadGltf(dir / "animated.gltf");
    EXPECT_TRUE(s.meshes.empty());
    EXPECT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instanceAnimations.size(), 1u);
    EXPECT_TRUE(animatesGeometry(s));
    applySceneTime(s, seconds);
    bakeAllInstances(s);
    // The sphere's centre is the mean of its two poles (the first and last vertices).
    return (s.meshes.at(0).positions.front() + s.meshes.at(0).positions.back()) * 0.5f;
}

TEST(GltfLoader, KeyframedTranslationPutsTheNodeWhereTheKeysSay) {
    const std::vector<float> keys = {0, 0, 0, 2, 0, 0, 2, 4, 0};
    expectNear(animatedPosition("LINEAR", keys, 0.5), {1, 0, 5}, 1e-5f);
    expectNear(animatedPosition("LINEAR", keys, 1.5), {2, 2, 5}, 1e-5f);
    expectNear(animatedPosition("LINEAR", keys, -1.0), {0, 0, 5}, 1e-5f);
    expectNear(animatedPosition("LINEAR", keys, 7.0), {2, 4, 5}, 1e-5f);
    expectNear(animatedPosition("STEP", keys, 1.9), {2, 0, 5}, 1e-5f);
    // Cubic spline: (in-tangent, value, out-tangent) per key. From key 0 (value 0, out-tangent
    // 4 along x) to key 1 (value 2, in-tangent 0) over 1 s, halfway: 0.5 * 0 + 0.125 * 4 + 0.5 * 2.
    const std::vector<float> cubic = {0, 0, 0, 0, 0, 0, 4, 0, 0,  //
                                      0, 0, 0, 2, 0, 0, 0, 0, 0,  //
                                      0, 0, 0, 2, 4, 0, 0, 0, 0};
    expectNear(animatedPosition("CUBICSPLINE", cubic, 0.5), {1.5f, 0, 5}, 1e-5f);
    expectNear(animatedPosition("CUBICSPLINE", cubic, 2.0), {2, 4, 5}, 1e-5f);
}

TEST_F(GltfScene, Materials) {
    const Mesh* tri = meshNamed(*scene_, "tri/0");
    const Material& e = scene_->materials[tri->material];
    EXPECT_EQ(e.name, "emitter");
    expectNear(e.albedo, {0.2f, 0.4f, 0.6f});
    EXPECT_FLOAT_EQ(e.metallic, 0.25f);
    EXPECT_FLOAT_EQ(e.roughness, 0.75f);
    expectNear(e.emission, {4, 2, 0});  // emissiveFactor * KHR_materials_emissive_strength
    EXPECT_FALSE(e.twoSided);
    EXPECT_FLOAT_EQ(e.specular, 1.0f);  // every glTF dielectric has its specular layer
    EXPECT_FLOAT_EQ(e.absorptionDistance, 0.0f);

    const Material& t = scene_->materials[meshNamed(*scene_, "quad/0")->material];
    EXPECT_TRUE(t.twoSided);
    EXPECT_FLOAT_EQ(t.alphaCutoff, 0.3f);
    EXPECT_FLOAT_EQ(t.transmission, 1.0f);
    EXPECT_FLOAT_EQ(t.ior, 1.33f);
    ASSERT_TRUE(t.albedoTexture.present());
    ASSERT_TRUE(t.metallicRoughnessTexture.present());
    EXPECT_NE(t.albedoTexture.texture, t.metallicRoughnessTexture.texture);  // sRGB vs linear copies
    EXPECT_EQ(t.albedoTexture.wrapU, Wrap::ClampToEdge);
    EXPECT_EQ(t.albedoTexture.wrapV, Wrap::MirroredRepeat);
    const Texture& base = scene_->textures[std::size_t(t.albedoTexture.texture)];
    EXPECT_TRUE(base.srgb);
    EXPECT_FALSE(scene_->textures[std::size_t(t.metallicRoughnessTexture.texture)].srgb);
    ASSERT_EQ(base.width, 2);
    EXPECT_EQ(base.rgba[0], 255);  // top-left red
    EXPECT_EQ(base.rgba[4 + 1], 255);  // top-right green
}

TEST_F(GltfScene, SpotLightTakesNodeTransform) {
    ASSERT_EQ(scene_->lights.size(), 1u);
    const Light& l = scene_->lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    expectNear(l.position, {10, 0, 2});
    expectNear(l.direction, {0, 0, -1});
    expectNear(l.color, {1, 0.5f, 0.25f});
    EXPECT_FLOAT_EQ(l.intensity, 100);
    EXPECT_FLOAT_EQ(l.innerConeRadians, 0.1f);
    EXPECT_FLOAT_EQ(l.outerConeRadians, 0.3f);
}

TEST_F(GltfScene, FirstCameraBecomesTheDefault) {
    expectNear(scene_->camera.position, {0, 0, 5});
    expectNear(scene_->camera.lookAt, {0, 0, 4});
    expectNear(scene_->camera.up, {0, 1, 0});
    EXPECT_NEAR(scene_->camera.fovYDegrees, radiansToDegrees(0.5), 1e-3);
}

TEST(GltfLoader, SpecularExtensionTurnsTheCoatOff) {
    Scene scene = loadGltf(dataDir() / "gltf/textured_quad.gltf");
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_FLOAT_EQ(scene.materials[0].specular, 0.0f);
}

// A sampler's NEAREST magFilter (9728) asks for the nearest texel, as pixel art does; others
// (or none) filter bilinearly.
TEST(GltfLoader, NearestMagFilterIsKept) {
    const std::filesystem::path dir = dataDir() / "gltf";
    std::ifstream in(dir / "textured_quad.gltf");
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string wrapT = "\"wrapT\": 33071";
    ASSERT_NE(json.find(wrapT), std::string::npos);
    std::string nearest = json;
    nearest.replace(nearest.find(wrapT), wrapT.size(), wrapT + ", \"magFilter\": 9728");
    EXPECT_EQ(loadGltfFromMemory(json, dir, "quad.gltf").materials[0].albedoTexture.filter, Filter::Linear);
    EXPECT_EQ(loadGltfFromMemory(nearest, dir, "quad.gltf").materials[0].albedoTexture.filter, Filter::Nearest);
}

TEST(GltfLoader, EmbeddedWithoutSceneUsesRootNodesAndFitsCamera) {
    Scene s = loadGltf(dataDir() / "gltf/triangle_embedded.gltf");
    EXPECT_EQ(s.triangleCount(), 1u);
    ASSERT_EQ(s.materials.size(), 1u);  // glTF's default material
    const Camera& c = s.camera;
    validateCamera(c);
    expectNear(c.lookAt, {0.5f, 0.5f, 0});
    float radius = 0.5f * std::sqrt(2.0f);
    EXPECT_NEAR(c.position.z, radius / std::sin(degreesToRadians(20.0)), 1e-4);
    EXPECT_FLOAT_EQ(c.fovYDegrees, 40.0f);
}

TEST(GltfLoader, MissingImageWarnsAndUsesChecker) {
    testing::internal::CaptureStderr();
    Scene s = loadGltf(dataDir() / "gltf/triangle_missing_image.glb");
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("penumbra: warning:"), std::string::npos);
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].width, 8);
    EXPECT_EQ(s.textures[0].name, "missing.png");
}

TEST(GltfLoader, BrokenFilesGiveErrorsThatSayWhere) {
    struct Case {
        const char* file;
        const char* expect;
    };
    for (const Case& c : {Case{"cycle.gltf", "cycle"}, Case{"accessor_overflow.gltf", "accessor 0"},
                          Case{"bad_stride.gltf", "byteStride"}, Case{"bad_mesh_index.gltf", "mesh 7"},
                          Case{"missing_buffer.gltf", "nowhere.bin"}}) {
        std::string e = errorOf([&] { loadGltf(dataDir() / "gltf" / c.file); });
        EXPECT_NE(e.find(c.expect), std::string::npos) << c.file << ": " << e;
        EXPECT_NE(e.find(c.file), std::string::npos) << e;
    }
}

TEST(GltfLoader, MalformedBytesGiveErrors) {
    std::string glb = test::readBytes(dataDir() / "gltf/triangle_missing_image.glb");
    std::string deep = "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + std::string(100000, '[') + std::string(100000, ']') + "}";
    const std::vector<std::string> bad = {
        "", "{", "null", "glTF", glb.substr(0, glb.size() / 2), glb.substr(0, 30), deep,
        R"({"asset":{"version":"2.0"}})",  // no triangles
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":1e30,"uri":"data:application/octet-stream;base64,AAAA"}]})",
        R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[5]}],"nodes":[{}]})",
    };
    for (const std::string& bytes : bad) {
        std::string e = errorOf([&] { loadGltfFromMemory(bytes, "/nonexistent", "bad.gltf"); });
        EXPECT_NE(e, "<no error>") << bytes.substr(0, 80);
    }
}

TEST(GltfLoader, DeepNodeChainIsRefused) {
    std::string nodes;
    for (int i = 0; i < 1000; ++i) {
        if (i > 0) nodes += ',';
        nodes.append("{\"children\":[").append(std::to_string(i + 1)).append("]}");
    }
    nodes += ",{}";
    std::string json = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[)" + nodes + "]}";
    std::string e = errorOf([&] { loadGltfFromMemory(json, "/nonexistent", "deep.gltf"); });
    EXPECT_NE(e.find("levels deep"), std::string::npos) << e;
}

// ---- Debian assimp-testmodels -----------------------------------------------------------------

TEST(GltfDebianAssets, BoxTexturedVariants) {
    for (const char* rel : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                            "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        const auto path = kAssimp / rel;
        PENUMBRA_REQUIRE_ASSET(path);
        SCOPED_TRACE(rel);
        Scene s = loadGltf(path);
        EXPECT_EQ(s.triangleCount(), 12u);
        ASSERT_EQ(s.meshes.size(), 1u);
        const Material& m = s.materials[s.meshes[0].material];
        ASSERT_TRUE(m.albedoTexture.present());
        const Texture& t = s.textures[std::size_t(m.albedoTexture.texture)];
        EXPECT_GT(t.width, 8);  // the real image, not the checker
        EXPECT_EQ(t.rgba.size(), std::size_t(t.width) * t.height * 4);
        EXPECT_EQ(s.meshes[0].uvs.size(), s.meshes[0].positions.size());
        validateCamera(s.camera);
    }
}

TEST(GltfDebianAssets, BrokenModelsFailCleanly) {
    for (const char* rel : {"RecursiveNodes/RecursiveNodes.gltf", "IndexOutOfRange/IndexOutOfRange.gltf",
                            "IndexOutOfRange/AllIndicesOutOfRange.gltf", "MissingBin/BoxTextured.gltf"}) {
        const auto path = kAssimp / rel;
        PENUMBRA_REQUIRE_ASSET(path);
        std::string e = errorOf([&] { loadGltf(path); });
        EXPECT_NE(e, "<no error>") << rel;
    }
    const auto inf = kAssimp / "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb";
    PENUMBRA_REQUIRE_ASSET(inf);
    // Either refused with a message or loaded into a valid scene.
    testing::internal::CaptureStderr();
    try {
        loadGltf(inf).validate();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("BoxWithInfinites"), std::string::npos) << e.what();
    }
    testing::internal::GetCapturedStderr();
}

TEST(GltfDebianAssets, CamerasFile) {
    const auto path = kAssimp / "cameras/Cameras.gltf";
    PENUMBRA_REQUIRE_ASSET(path);
    testing::internal::CaptureStderr();
    Scene s = loadGltf(path);
    testing::internal::GetCapturedStderr();
    validateCamera(s.camera);
    EXPECT_GT(s.triangleCount(), 0u);
}

// Every glTF file in the package either loads into a valid scene or fails with an Error.
TEST(GltfDebianAssets, EveryFileLoadsOrFailsCleanly) {
    PENUMBRA_REQUIRE_ASSET(kAssimp);
    int loaded = 0, refused = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kAssimp)) {
        const auto ext = entry.path().extension();
        if (ext != ".gltf" && ext != ".glb") continue;
        testing::internal::CaptureStderr();
        try {
            loadGltf(entry.path()).validate();
            ++loaded;
        } catch (const Error&) {
            ++refused;
        }
        testing::internal::GetCapturedStderr();
    }
    EXPECT_GT(loaded, 10);
    std::printf("loaded %d, refused %d\n", loaded, refused);
}

}  // namespace
}  // namespace penumbra
