// PLY importer: the same cube in every encoding (ASCII, binary little and big endian, gzip),
// attributes, polygons and degenerate faces, and malformed files (one-line errors that say where).
#include "scene/io/ply.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "io_test_util.h"
#include "scene/io/load.h"

namespace penumbra {
namespace {

using test::dataDir;
using test::readBytes;
using test::errorOf;

class PlyCube : public ::testing::TestWithParam<const char*> {};

TEST_P(PlyCube, HasTheCubesCountsAndBounds) {
    Scene s = loadSceneFile(dataDir() / "ply" / GetParam());
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.triangleCount(), 12u);  // six quads
    const Aabb b = s.bounds();
    EXPECT_EQ(b.lo, Vec3(-1, -2, -3));
    EXPECT_EQ(b.hi, Vec3(1, 2, 3));
    const Mesh& m = s.meshes[0];
    // No normals in the file: crease normals split the cube's corners, one normal per face.
    EXPECT_EQ(m.positions.size(), 24u);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        const Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
                   p2 = m.positions[m.indices[3 * t + 2]];
        const Vec3 face = normalize(cross(p1 - p0, p2 - p0));
        for (int k = 0; k < 3; ++k) EXPECT_GT(dot(m.normals[m.indices[3 * t + k]], face), 0.9999f);
    }
    EXPECT_TRUE(m.uvs.empty());
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].albedo, Vec3(0.8f));
}

INSTANTIATE_TEST_SUITE_P(Encodings, PlyCube,
                         ::testing::Values("cube_ascii.ply", "cube_le.ply", "cube_be.ply",
                                           "cube_ascii.ply.gz"));

TEST(PlyLoader, ReadsNormalsUvsColoursAndPolygons) {
    Scene s = loadPly(dataDir() / "ply/pentagon_attributes.ply");
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.triangleCount(), 3u);  // the pentagon, fanned; the two degenerate faces are skipped
    EXPECT_EQ(m.positions.size(), 5u);  // the file's normals are used: nothing is split
    ASSERT_EQ(m.normals.size(), 5u);
    for (const Vec3& n : m.normals) EXPECT_EQ(n, Vec3(0, 0, 1));
    ASSERT_EQ(m.uvs.size(), 5u);
    EXPECT_FLOAT_EQ(m.uvs[1].x, 1.0f);  // s
    EXPECT_FLOAT_EQ(m.uvs[1].y, 1.0f);  // 1 - t: the scene's v runs down
    EXPECT_FLOAT_EQ(m.uvs[2].y, 0.0f);
    // Pure red vertices: the material's albedo is their (linear) average.
    EXPECT_EQ(s.materials[0].albedo, Vec3(1, 0, 0));
    EXPECT_EQ(s.bounds().hi, Vec3(1.5f, 1.5f, 0));
}

TEST(PlyLoader, TheEncodingsAgreeExactly) {
    Scene a = loadPly(dataDir() / "ply/cube_ascii.ply"), b = loadPly(dataDir() / "ply/cube_le.ply"),
          c = loadPly(dataDir() / "ply/cube_be.ply");
    EXPECT_EQ(a.meshes[0].indices, b.meshes[0].indices);
    EXPECT_EQ(a.meshes[0].indices, c.meshes[0].indices);
    for (std::size_t i = 0; i < a.meshes[0].positions.size(); ++i) {
        EXPECT_EQ(a.meshes[0].positions[i], b.meshes[0].positions[i]);
        EXPECT_EQ(a.meshes[0].positions[i], c.meshes[0].positions[i]);
    }
}

// Each malformed file must give one line naming the file and, where it can, the line or element.
struct Malformed {
    const char* what;
    std::string bytes;
    const char* expected;  // a part of the message
};

std::string asciiCube(const std::string& body) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
           "float z\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
           body;
}

std::string binaryTriangle(int count, const std::string& body) {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(count) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
           "property list uchar int vertex_indices\nend_header\n" +
           body;
}

TEST(PlyLoader, MalformedFilesGiveOneLineErrors) {
    const Malformed cases[] = {
        {"not ply", "plx\nformat ascii 1.0\n", "t.ply:1: not a PLY file"},
        {"no end_header", "ply\nformat ascii 1.0\nelement vertex 0\n", "no 'end_header'"},
        {"no format", "ply\nelement vertex 0\nend_header\n", "no 'format' line"},
        {"unknown format", "ply\nformat binary_middle_endian 1.0\nend_header\n",
         "t.ply:2: unknown format"},
        {"bad type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n",
         "t.ply:4: unknown property type 'real'"},
        {"float list count",
         "ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\nend_header\n",
         "t.ply:4: a list's count type must be an integer type"},
        {"property first", "ply\nformat ascii 1.0\nproperty float x\nend_header\n",
         "before any 'element'"},
        {"absurd count", binaryTriangle(1000000000, std::string(100, '\0')),
         "claims 1000000000 entries"},
        {"huge count",
         "ply\nformat ascii 1.0\nelement vertex 99999999999999\nproperty float x\nend_header\n",
         "t.ply:3: element 'vertex' claims 99999999999999 entries"},
        {"no xyz", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
         "needs properties x, y and z"},
        {"not a number", asciiCube("0 0 0\n1 0 0\n0 1 zero\n3 0 1 2\n"),
         "t.ply:12: vertex 2: expected a number, found 'zero'"},
        {"index out of range", asciiCube("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
         "t.ply:13: face 0: refers to vertex 3, but the file has 3 vertices"},
        {"negative index", asciiCube("0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"), "refers to vertex -1"},
        {"truncated ascii", asciiCube("0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
         "face 0: the file ends inside it"},
        {"nan vertex", asciiCube("0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
         "vertex 1: a coordinate is not a finite"},
        {"truncated binary", binaryTriangle(3, std::string(36, '\0') + "\x03\x01"),
         "t.ply: face 0: the file ends inside it"},
        {"binary list too long", binaryTriangle(3, std::string(36, '\0') + "\xff\x01\x02"),
         "face 0: the file ends inside it"},
        {"no faces",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 0\n",
         "no 'face' element"},
        {"only degenerate", asciiCube("0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"),
         "t.ply: no face can be rendered: the file has 1 face without area"},
        {"only overflowing", asciiCube("0 0 0\n1 0 0\n3e38 3e38 0\n3 0 1 2\n"),
         "t.ply: no face can be rendered: the file has 1 face with coordinates that are not finite"},
        {"corrupt gzip", std::string("\x1f\x8b\x08\x00garbage", 11), "t.ply: "},
    };
    for (const Malformed& c : cases) {
        const std::string e = errorOf([&] { loadPlyFromMemory(c.bytes, "t.ply"); });
        EXPECT_NE(e.find(c.expected), std::string::npos) << c.what << ": " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << c.what << ": " << e;
        EXPECT_EQ(e.rfind("t.ply", 0), 0u) << c.what << ": " << e;
    }
}

TEST(PlyLoader, ExtensionAndContentMustAgree) {
    const std::string e = errorOf([] { loadSceneFile(dataDir() / "obj/cube.obj.ply"); });
    EXPECT_NE(e.find("no such file"), std::string::npos) << e;
    const auto tmp = std::filesystem::temp_directory_path() / "penumbra_ply_test_not_gz.ply.gz";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << readBytes(dataDir() / "ply/cube_ascii.ply");
    }
    const std::string e2 = errorOf([&] { loadSceneFile(tmp); });
    std::filesystem::remove(tmp);
    EXPECT_NE(e2.find("does not look like a gzip-compressed file"), std::string::npos) << e2;
}

}  // namespace
}  // namespace penumbra
