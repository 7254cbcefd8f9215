// OBJ/MTL importer: triangulation, materials, textures, negative indices, crease normals,
// missing MTL, malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "core/error.h"
#include "io_test_util.h"
#include "scene/face_check.h"
#include "scene/io/obj.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

using test::dataDir;
using test::errorOf;

const Mesh* meshNamed(const Scene& s, const std::string& name) {
    for (const Mesh& m : s.meshes)
        if (m.name == name) return &m;
    return nullptr;
}

TEST(ObjLoader, QuadAndNegativeIndexPolygonAreTriangulatedPerMaterial) {
    Scene s = loadObj(dataDir() / "obj/quad_tex.obj");
    EXPECT_EQ(s.triangleCount(), 2u + 3u);  // quad + pentagon
    ASSERT_EQ(s.meshes.size(), 2u);         // one mesh per used material
    Aabb b = s.bounds();
    EXPECT_EQ(b.lo, Vec3(0, 0, 0));
    EXPECT_EQ(b.hi, Vec3(3.5f, 2, 0));

    const Mesh* quad = meshNamed(s, "textured");
    ASSERT_NE(quad, nullptr);
    EXPECT_EQ(quad->triangleCount(), 2u);
    EXPECT_EQ(quad->positions.size(), 4u);
    ASSERT_EQ(quad->normals.size(), 4u);
    EXPECT_EQ(quad->normals[0], Vec3(0, 0, 1));
    ASSERT_EQ(quad->uvs.size(), 4u);
    // OBJ vt (0,0) is the bottom-left; the scene's v runs down from the top row.
    for (std::size_t i = 0; i < 4; ++i)
        if (quad->positions[i] == Vec3(0, 0, 0)) {
            EXPECT_FLOAT_EQ(quad->uvs[i].y, 1.0f);
        }

    const Material& tex = s.materials[quad->material];
    EXPECT_FLOAT_EQ(tex.albedo.x, 0.5f);
    EXPECT_FLOAT_EQ(tex.albedo.y, 0.25f);
    EXPECT_FLOAT_EQ(tex.albedo.z, 1.0f);
    EXPECT_NEAR(tex.roughness, std::sqrt(2.0f / 100.0f), 1e-5f);
    EXPECT_EQ(tex.metallic, 0.0f);
    ASSERT_TRUE(tex.albedoTexture.present());
    const Texture& t = s.textures[std::size_t(tex.albedoTexture.texture)];
    EXPECT_EQ(t.width, 2);
    EXPECT_EQ(t.height, 2);
    EXPECT_TRUE(t.srgb);
    EXPECT_EQ(t.rgba[0], 255);  // top-left texel is red
    EXPECT_EQ(t.rgba[1], 0);
    EXPECT_EQ(t.rgba[4 * 2 + 2], 255);  // bottom-left is blue

    const Mesh* penta = meshNamed(s, "glass");
    ASSERT_NE(penta, nullptr);
    EXPECT_EQ(penta->triangleCount(), 3u);
    const Material& glass = s.materials[penta->material];
    EXPECT_EQ(glass.transmission, 1.0f);
    EXPECT_FLOAT_EQ(glass.ior, 1.45f);
    EXPECT_EQ(glass.opacity, 1.0f);
    // Flat pentagon without normals: every generated normal is +Z.
    ASSERT_EQ(penta->normals.size(), penta->positions.size());
    for (Vec3 n : penta->normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST(ObjLoader, MissingTextureBecomesCheckerWithWarning) {
    testing::internal::CaptureStderr();
    Scene s = loadObj(dataDir() / "obj/quad_tex.obj");
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("penumbra: warning:"), std::string::npos);
    EXPECT_NE(err.find("missing_texture.png"), std::string::npos);
    const Material* lamp = nullptr;
    for (const Material& m : s.materials)
        if (m.name == "lamp") lamp = &m;
    ASSERT_NE(lamp, nullptr);
    EXPECT_EQ(lamp->emission, Vec3(4, 3, 2));
    ASSERT_TRUE(lamp->albedoTexture.present());
    const Texture& t = s.textures[std::size_t(lamp->albedoTexture.texture)];
    EXPECT_EQ(t.width, 8);
    EXPECT_EQ(t.rgba[0], 255);  // magenta
    EXPECT_EQ(t.rgba[1], 0);
    EXPECT_EQ(t.rgba[2], 255);
}

TEST(ObjLoader, MissingMtlWarnsAndUsesGrey) {
    testing::internal::CaptureStderr();
    Scene s = loadObj(dataDir() / "obj/missing_mtl.obj");
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("penumbra: warning:"), std::string::npos);
    EXPECT_NE(err.find("does_not_exist.mtl"), std::string::npos);
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.materials[s.meshes[0].material].albedo, Vec3(0.8f));
}

TEST(ObjLoader, CubeGetsFlatNormalsPerFace) {
    Scene s = loadObj(dataDir() / "obj/cube.obj");
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.triangleCount(), 12u);
    EXPECT_EQ(m.positions.size(), 24u);
    std::set<std::tuple<float, float, float, float, float, float>> distinct;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        Vec3 n = m.normals[i];
        EXPECT_NEAR(std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z), 1.0f, 1e-6f);  // axis-aligned
        distinct.insert({m.positions[i].x, m.positions[i].y, m.positions[i].z, n.x, n.y, n.z});
    }
    EXPECT_EQ(distinct.size(), 24u);
    // Outward: the normal points away from the cube's centre.
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        EXPECT_GT(dot(m.normals[i], m.positions[i] - Vec3(0.5f)), 0.0f);
}

TEST(ObjLoader, SmoothSphereKeepsSharedVertices) {
    std::ostringstream obj;
    const int rings = 16, segments = 32;
    int count = 0;
    obj << "v 0 1 0\n";
    ++count;
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            double th = kPi * r / rings, ph = 2 * kPi * s / segments;
            obj << "v " << std::sin(th) * std::cos(ph) << " " << std::cos(th) << " " << -std::sin(th) * std::sin(ph) << "\n";
            ++count;
        }
    obj << "v 0 -1 0\n";
    ++count;
    auto ring = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) obj << "f 1 " << ring(1, s) << " " << ring(1, s + 1) << "\n";
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s)
            obj << "f " << ring(r, s) << " " << ring(r + 1, s) << " " << ring(r + 1, s + 1) << " " << ring(r, s + 1)
                << "\n";
    for (int s = 0; s < segments; ++s) obj << "f " << count << " " << ring(rings - 1, s + 1) << " " << ring(rings - 1, s) << "\n";
    Scene scene = loadObjFromMemory(obj.str(), "", ".", "sphere.obj");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& m = scene.meshes[0];
    EXPECT_EQ(m.positions.size(), std::size_t(count));  // nothing split
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        EXPECT_GT(dot(m.normals[i], normalize(m.positions[i])), 0.99f);
}

TEST(ObjLoader, NonFiniteVertexNamesTheLine) {
    std::string e = errorOf([] { loadObj(dataDir() / "obj/nan_vertex.obj"); });
    EXPECT_NE(e.find("nan_vertex.obj:4"), std::string::npos) << e;
    EXPECT_NE(e.find("finite"), std::string::npos) << e;
}

TEST(ObjLoader, BadIndexNamesTheLine) {
    std::string e = errorOf([] { loadObj(dataDir() / "obj/bad_index.obj"); });
    EXPECT_NE(e.find("bad_index.obj:5"), std::string::npos) << e;
    EXPECT_NE(e.find("vertex 7"), std::string::npos) << e;
}

TEST(ObjLoader, NegativeIndexBeforeFirstVertexIsAnError) {
    std::string e = errorOf([] { loadObjFromMemory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "", ".", "rel.obj"); });
    EXPECT_NE(e.find("rel.obj:4"), std::string::npos) << e;
}

TEST(ObjLoader, DegenerateFacesAreSkipped) {
    testing::internal::CaptureStderr();
    Scene s = loadObj(dataDir() / "obj/degenerate.obj");
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.triangleCount(), 1u);
    EXPECT_NE(err.find("degenerate"), std::string::npos) << err;
}

TEST(FaceCheck, NonFiniteAndOverflowingFacesAreToldApart) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(faceDefect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), FaceDefect::None);
    EXPECT_EQ(faceDefect({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), FaceDefect::Degenerate);
    EXPECT_EQ(faceDefect({0, 0, 0}, {1, 0, 0}, {nan, 1, 0}), FaceDefect::NotFinite);
    EXPECT_EQ(faceDefect({-3e38f, 0, 0}, {3e38f, 0, 0}, {0, 1, 0}), FaceDefect::NotFinite);  // an edge overflows
    EXPECT_EQ(faceDefect({0, 0, 0}, {1, 0, 0}, {3e38f, 3e38f, 0}), FaceDefect::NotFinite);  // |normal|^2 overflows
}

// Finite corners whose triangle overflows float arithmetic: the renderer would get NaN normals
// and a black image, so the face is skipped and said to be.
TEST(ObjLoader, OverflowingFacesAreSkippedWithAWarning) {
    testing::internal::CaptureStderr();
    Scene s = loadObjFromMemory("v 0 0 0\nv 1 0 0\nv 3e38 3e38 0\nf 1 2 3\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf 4 5 6\n", "",
                                ".", "big.obj");
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.triangleCount(), 1u);
    EXPECT_NE(err.find("big.obj: skipped 1 face with coordinates that are not finite"), std::string::npos) << err;
}

TEST(ObjLoader, NoRenderableFaceLeftIsAnError) {
    testing::internal::CaptureStderr();
    std::string e = errorOf([] { loadObjFromMemory("v 0 0 0\nv 1 0 0\nv 3e38 3e38 0\nf 1 2 3\n", "", ".", "big.obj"); });
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(e.find("big.obj: no face can be rendered"), std::string::npos) << e;
    EXPECT_NE(e.find("not finite"), std::string::npos) << e;
    EXPECT_EQ(err, "") << "the error alone says what is wrong";
    e = errorOf([] { loadObjFromMemory("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "", ".", "flat.obj"); });
    EXPECT_NE(e.find("flat.obj: no face can be rendered: the file has 1 face without area"), std::string::npos) << e;
}

TEST(ObjLoader, MtlFromMemoryAndMaterialHints) {
    const char* mtl =
        "newmtl mirror\nKd 0 0 0\nKs 0.9 0.9 0.9\nNs 1000\nillum 5\n"
        "newmtl cutout\nKd 1 0 0\nd 0.25\n"
        "newmtl tr\nKd 1 1 1\nTr 0.75\n";
    const char* obj =
        "mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl mirror\nf 1 2 3\nusemtl cutout\nf 1 2 3\nusemtl tr\nf 1 2 3\n";
    Scene s = loadObjFromMemory(obj, mtl, ".", "mem.obj");
    ASSERT_EQ(s.meshes.size(), 3u);
    const Material& mirror = s.materials[meshNamed(s, "mirror")->material];
    EXPECT_EQ(mirror.metallic, 1.0f);
    EXPECT_FLOAT_EQ(mirror.albedo.x, 0.9f);
    EXPECT_LT(mirror.roughness, 0.05f);
    EXPECT_FLOAT_EQ(s.materials[meshNamed(s, "cutout")->material].opacity, 0.25f);
    EXPECT_FLOAT_EQ(s.materials[meshNamed(s, "tr")->material].opacity, 0.25f);
}

TEST(ObjLoader, MalformedInputsGiveErrors) {
    const std::vector<std::string> bad = {
        "",                                           // nothing
        "v 0 0 0\nv 1 0 0\nv 0 1 0\n",               // no faces
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",      // zero index
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/5 2/5 3/5\n",  // texcoord out of range
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//9 2//9 3//9\n",
        "v 0 0 0\nv 1 0\nf 1 2",                      // truncated
        "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    };
    for (const std::string& text : bad) {
        testing::internal::CaptureStderr();
        bool threw = false;
        try {
            loadObjFromMemory(text, "", ".", "bad.obj");
        } catch (const Error&) {
            threw = true;
        }
        testing::internal::GetCapturedStderr();
        // "v nan" is read as 0 by tinyobjloader; everything else must be refused.
        if (text.rfind("v nan", 0) != 0) {
            EXPECT_TRUE(threw) << text;
        }
    }
}

TEST(ObjLoader, HugePolygonIsRefusedOrTriangulated) {
    std::ostringstream obj;
    const int n = 300;
    for (int i = 0; i < n; ++i)
        obj << "v " << std::cos(2 * kPi * i / n) << " " << std::sin(2 * kPi * i / n) << " 0\n";
    obj << "f";
    for (int i = 1; i <= n; ++i) obj << " " << i;
    obj << "\n";
    try {
        Scene s = loadObjFromMemory(obj.str(), "", ".", "big.obj");
        EXPECT_EQ(s.triangleCount(), std::size_t(n - 2));
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("255"), std::string::npos) << e.what();
    }
}

TEST(ObjLoader, DebianBunny) {
    const std::filesystem::path bunny = "/usr/share/glmark2/models/bunny.obj";
    PENUMBRA_REQUIRE_ASSET(bunny);
    Scene s = loadObj(bunny);
    EXPECT_EQ(s.triangleCount(), 69666u);
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].normals.size(), s.meshes[0].positions.size());
    validateCamera(s.camera);
}

}  // namespace
}  // namespace penumbra
