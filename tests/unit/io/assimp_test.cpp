// Assimp importer: hand-written STL, OFF and Collada files (counts, bounds, winding, node
// transforms, materials), Debian's assimp test models (every promised extension loads; the same
// model in text and binary encodings agrees), and malformed files (one-line errors).
#include "scene/io/assimp_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "core/error.h"
#include "io_test_util.h"
#include "scene/io/load.h"

namespace penumbra {
namespace {

using test::dataDir;
using test::readBytes;
using test::errorOf;

const std::filesystem::path kModels = "/usr/share/assimp/models";

Vec3 faceNormal(const Mesh& m, std::size_t t) {
    const Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
               p2 = m.positions[m.indices[3 * t + 2]];
    return normalize(cross(p1 - p0, p2 - p0));
}

// Every triangle of a closed convex mesh winds counter-clockwise seen from outside (its normal
// points away from `inside`), and its shading normals agree with it (flat faces).
void expectOutwardFlatFaces(const Scene& s, Vec3 inside) {
    for (const Mesh& m : s.meshes) {
        ASSERT_EQ(m.normals.size(), m.positions.size());
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            const Vec3 n = faceNormal(m, t);
            EXPECT_GT(dot(n, m.positions[m.indices[3 * t]] - inside), 0.0f) << m.name << " triangle " << t;
            for (int k = 0; k < 3; ++k) EXPECT_GT(dot(m.normals[m.indices[3 * t + k]], n), 0.999f);
        }
    }
}

TEST(AssimpLoader, AsciiStlTetrahedron) {
    const Scene s = loadSceneFile(dataDir() / "assimp/tetrahedron.stl");
    EXPECT_EQ(s.triangleCount(), 4u);
    EXPECT_EQ(s.bounds().lo, Vec3(0, 0, 0));
    EXPECT_EQ(s.bounds().hi, Vec3(1, 2, 3));
    expectOutwardFlatFaces(s, Vec3{0.25f, 0.5f, 0.75f});
    ASSERT_FALSE(s.materials.empty());
    for (const Mesh& m : s.meshes) EXPECT_LT(m.material, s.materials.size());
}

TEST(AssimpLoader, OffBoxQuadsAreTriangulatedWithCreaseNormals) {
    const Scene s = loadSceneFile(dataDir() / "assimp/box.off");
    EXPECT_EQ(s.triangleCount(), 12u);
    EXPECT_EQ(s.bounds().lo, Vec3(-1, -2, -3));
    EXPECT_EQ(s.bounds().hi, Vec3(1, 2, 3));
    // No normals in the file: crease normals, one per face, so the corners are split.
    expectOutwardFlatFaces(s, Vec3{0.0f});
    std::size_t vertices = 0;
    for (const Mesh& m : s.meshes) vertices += m.positions.size();
    EXPECT_EQ(vertices, 24u);
}

class ColladaQuads : public ::testing::Test {
protected:
    void SetUp() override { s = loadSceneFile(dataDir() / "assimp/two_quads.dae"); }
    const Mesh& meshNamed(const std::string& name) {
        for (const Mesh& m : s.meshes)
            if (m.name == name) return m;
        ADD_FAILURE() << "no mesh " << name;
        return s.meshes.at(0);
    }
    Scene s;
};

TEST_F(ColladaQuads, NodeTransformsAreBakedAndMirroringKeepsFrontFaces) {
    ASSERT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(s.triangleCount(), 4u);
    EXPECT_EQ(s.bounds().lo, Vec3(0, 0, -2));
    EXPECT_EQ(s.bounds().hi, Vec3(5, 2, 0));
    const Mesh& glossy = meshNamed("glossy-quad");
    const Mesh& lamp = meshNamed("lamp-quad");
    Aabb lampBox;
    for (Vec3 p : lamp.positions) lampBox.grow(p);
    EXPECT_EQ(lampBox.lo, Vec3(3, 0, 0));  // x = 5 - 2 [0, 1]
    EXPECT_EQ(lampBox.hi, Vec3(5, 2, 0));
    // Both quads face +z in the file; the mirrored copy must still face +z (winding flipped).
    for (const Mesh* m : {&glossy, &lamp}) {
        ASSERT_EQ(m->normals.size(), m->positions.size());
        for (std::size_t t = 0; t < m->triangleCount(); ++t) {
            EXPECT_GT(faceNormal(*m, t).z, 0.999f) << m->name;
            for (int k = 0; k < 3; ++k) EXPECT_GT(m->normals[m->indices[3 * t + k]].z, 0.999f) << m->name;
        }
    }
    // The file's (s, t) = (0, 0) is the bottom left; the scene model's origin is the top left.
    ASSERT_EQ(lamp.uvs.size(), lamp.positions.size());
    for (std::size_t i = 0; i < lamp.positions.size(); ++i) {
        const Vec3 p = lamp.positions[i];
        EXPECT_NEAR(lamp.uvs[i].x, (5.0f - p.x) / 2.0f, 1e-6f);
        EXPECT_NEAR(lamp.uvs[i].y, 1.0f - p.y / 2.0f, 1e-6f);
    }
}

TEST_F(ColladaQuads, PhongAndLambertMaterialsAreMapped) {
    const Material& glossy = s.materials.at(meshNamed("glossy-quad").material);
    const Material& lamp = s.materials.at(meshNamed("lamp-quad").material);
    EXPECT_EQ(glossy.name, "glossy");
    EXPECT_NEAR(glossy.albedo.x, 0.2f, 1e-6f);
    EXPECT_NEAR(glossy.albedo.y, 0.4f, 1e-6f);
    EXPECT_NEAR(glossy.albedo.z, 0.6f, 1e-6f);
    EXPECT_EQ(glossy.specular, 1.0f);
    EXPECT_NEAR(glossy.roughness, std::sqrt(2.0f / 100.0f), 1e-6f);  // Ns 98
    EXPECT_FALSE(glossy.isEmissive());
    EXPECT_FALSE(glossy.albedoTexture.present());
    EXPECT_EQ(glossy.opacity, 1.0f);

    EXPECT_EQ(lamp.name, "lamp");
    EXPECT_EQ(lamp.emission, Vec3(2.0f, 1.0f, 0.5f));
    EXPECT_EQ(lamp.specular, 0.0f);  // Lambert: no coat
    EXPECT_EQ(lamp.roughness, 1.0f);
    EXPECT_NEAR(lamp.opacity, 0.5f, 1e-6f);
    ASSERT_TRUE(lamp.albedoTexture.present());
    const Texture& tex = s.textures.at(std::size_t(lamp.albedoTexture.texture));
    EXPECT_EQ(tex.width, 2);  // the real file, not the 8x8 missing-texture checker
    EXPECT_EQ(tex.height, 2);
    EXPECT_TRUE(tex.srgb);
}

TEST(AssimpLoader, ColladaZUpIsTurnedToYUp) {
    std::string dae = readBytes(dataDir() / "assimp/two_quads.dae");
    dae.replace(dae.find("Y_UP"), 4, "Z_UP");
    const Scene s = loadAssimpFromMemory(dae, "zup.dae", "dae");
    // (x, y, z) in the file is (x, z, -y) with +y up: the quads' height becomes depth.
    const Aabb b = s.bounds();
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.lo[k], Vec3(0, -2, -2)[k], 1e-6f) << k;
        EXPECT_NEAR(b.hi[k], Vec3(5, 0, 0)[k], 1e-6f) << k;
    }
}

TEST(AssimpLoader, FromMemoryMatchesTheFile) {
    const Scene file = loadSceneFile(dataDir() / "assimp/tetrahedron.stl");
    const Scene memory = loadAssimpFromMemory(readBytes(dataDir() / "assimp/tetrahedron.stl"), "t.stl", "stl");
    EXPECT_EQ(memory.triangleCount(), file.triangleCount());
    EXPECT_EQ(memory.bounds().lo, file.bounds().lo);
    EXPECT_EQ(memory.bounds().hi, file.bounds().hi);
}

TEST(AssimpLoader, MalformedFilesGiveOneLineErrors) {
    const auto dir = std::filesystem::temp_directory_path() / "penumbra-assimp-bad";
    std::filesystem::create_directories(dir);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"empty.fbx", ""},
        {"junk.dae", "<COLLADA><library_geometries><geometry><mesh><source"},
        {"junk.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0\n"},
        {"nan.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex nan 0 0\nvertex 0 1 0\n"
                    "endloop\nendfacet\nendsolid x\n"},
        {"count.off", "OFF\n100000000 1 0\n0 0 0\n"},
        {"binary.3ds", std::string("\x4d\x4d\xff\xff\xff\x7f\x3d\x3d", 8)},
        {"no_count.dae", "<?xml version=\"1.0\"?><COLLADA version=\"1.4.1\"><library_geometries><geometry><mesh>"
                         "<source id=\"p\"><float_array id=\"a\">0 0 0</float_array></source></mesh></geometry>"
                         "</library_geometries></COLLADA>"},
        {"truncated.x", "xof 0303txt 0032\nFrame { Mesh { 3; 0;0;0;, 1;0;"},
    };
    for (const auto& [file, bytes] : cases) {
        SCOPED_TRACE(file);
        std::ofstream(dir / file, std::ios::binary) << bytes;
        const std::filesystem::path path = dir / file;  // clang 14 cannot capture a structured binding
        const std::string error = errorOf([&] { (void)loadSceneFile(path); });
        EXPECT_NE(error, "<no error>");
        EXPECT_NE(error.find(file), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
    EXPECT_NE(errorOf([&] { (void)loadSceneFile(dir / "nan.stl"); }).find("no triangles"), std::string::npos);
    std::filesystem::create_directories(dir / "folder.fbx");
    EXPECT_NE(errorOf([&] { (void)loadSceneFile(dir / "folder.fbx"); }).find("not a regular file"), std::string::npos);
    std::filesystem::remove_all(dir);
}

// ---- Debian assimp-testmodels -----------------------------------------------------------------

struct Model {
    const char* path;
    std::size_t minTriangles;
};

class AssimpTestModel : public ::testing::TestWithParam<Model> {};

TEST_P(AssimpTestModel, LoadsWithGeometryAndValidMaterials) {
    const std::filesystem::path path = kModels / GetParam().path;
    PENUMBRA_REQUIRE_ASSET(path);
    const Scene s = loadSceneFile(path);
    EXPECT_GE(s.triangleCount(), GetParam().minTriangles);
    const Aabb b = s.bounds();
    EXPECT_TRUE(isFinite(b.lo) && isFinite(b.hi));
    EXPECT_GT(maxComponent(b.hi - b.lo), 0.0f);
}

// One model per promised extension (assimpExtensions()).
INSTANTIATE_TEST_SUITE_P(
    EveryExtension, AssimpTestModel,
    ::testing::Values(Model{"FBX/box.fbx", 12}, Model{"Collada/duck.dae", 1000}, Model{"3DS/fels.3ds", 100},
                      Model{"STL/Spider_binary.stl", 1000}, Model{"X/test_cube_text.x", 12},
                      Model{"OFF/Wuson.off", 1000}, Model{"ASE/ThreeCubesGreen.ASE", 36},
                      Model{"LWO/LWO2/box_2uv_1unused.lwo", 12}, Model{"MS3D/jeep1.ms3d", 100},
                      Model{"AC/SphereWithLight.ac", 100}, Model{"3MF/box.3mf", 12}, Model{"B3D/WusonBlitz.b3d", 1000},
                      Model{"DXF/wuson.dxf", 1000}, Model{"MD2/faerie.md2", 100}, Model{"MD5/SimpleCube.md5mesh", 12},
                      Model{"SMD/triangle.smd", 1}, Model{"NFF/NFF/cylinder.nff", 10},
                      Model{"OpenGEX/Example.ogex", 1}),
    [](const auto& model) {
        std::string name = std::filesystem::path(model.param.path).stem().string();
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return name + "_" + std::filesystem::path(model.param.path).extension().string().substr(1);
    });

TEST(AssimpTestModels, TextAndBinaryEncodingsAgree) {
    for (auto [a, b] : {std::pair{"STL/Spider_ascii.stl", "STL/Spider_binary.stl"},
                        std::pair{"X/test_cube_text.x", "X/test_cube_binary.x"}}) {
        SCOPED_TRACE(a);
        PENUMBRA_REQUIRE_ASSET(kModels / a);
        PENUMBRA_REQUIRE_ASSET(kModels / b);
        const Scene sa = loadSceneFile(kModels / a), sb = loadSceneFile(kModels / b);
        EXPECT_EQ(sa.triangleCount(), sb.triangleCount());
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(sa.bounds().lo[k], sb.bounds().lo[k], 1e-3f);
            EXPECT_NEAR(sa.bounds().hi[k], sb.bounds().hi[k], 1e-3f);
        }
    }
}

TEST(AssimpTestModels, ThreeDsDiffuseTextureIsLoaded) {
    const std::filesystem::path path = kModels / "3DS/cube_with_diffuse_texture.3DS";
    PENUMBRA_REQUIRE_ASSET(path);
    const Scene s = loadSceneFile(path);
    bool found = false;
    for (const Material& m : s.materials) {
        if (!m.albedoTexture.present()) continue;
        found = true;
        const Texture& t = s.textures.at(std::size_t(m.albedoTexture.texture));
        EXPECT_NE(t.width, 8) << "the missing-texture checker, not " << t.name;
    }
    EXPECT_TRUE(found);
}

}  // namespace
}  // namespace penumbra
