// Crease-angle normal generation and the fitted default camera.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/io/normals.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

// Two triangles sharing the edge (0,0,0)-(0,1,0), both facing roughly +Z.
Mesh hinge(float degrees) {  // degrees between the two face normals
    Mesh m;
    float a = degreesToRadians(degrees);
    m.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {-std::cos(a), 0, std::sin(a)}};
    m.indices = {0, 2, 1, 0, 1, 3};
    return m;
}

TEST(CreaseNormals, GentleFoldIsSmoothed) {
    Mesh m = hinge(10.0f);
    generateCreaseNormals(m, 60.0f);
    EXPECT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.normals.size(), 4u);
}

TEST(CreaseNormals, SharpFoldIsSplit) {
    Mesh m = hinge(90.0f);
    generateCreaseNormals(m, 60.0f);
    EXPECT_EQ(m.positions.size(), 6u);  // the two shared vertices are duplicated
    for (std::size_t t = 0; t < 2; ++t) {
        Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
             p2 = m.positions[m.indices[3 * t + 2]];
        Vec3 face = normalize(cross(p1 - p0, p2 - p0));
        for (int k = 0; k < 3; ++k) EXPECT_GT(dot(m.normals[m.indices[3 * t + k]], face), 0.9999f);
    }
}

TEST(CreaseNormals, UvSeamIsSmoothedAcross) {
    Mesh m = hinge(10.0f);
    // Split vertex 1 for a UV seam: same position, different uv.
    m.positions.push_back(m.positions[1]);
    m.uvs = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {0.5f, 1}};
    m.indices[4] = 4;
    generateCreaseNormals(m, 60.0f);
    EXPECT_EQ(m.positions.size(), 5u);
    EXPECT_EQ(m.normals[m.indices[2]], m.normals[m.indices[4]]);
    EXPECT_EQ(m.uvs.size(), 5u);
}

TEST(FitCamera, SphereFitsInFov) {
    Aabb box;
    box.grow({-1, -1, -1});
    box.grow({1, 1, 1});
    Camera c = cameraFittingBounds(box, 40.0f);
    EXPECT_EQ(c.lookAt, Vec3(0, 0, 0));
    EXPECT_NEAR(c.position.z, std::sqrt(3.0f) / std::sin(degreesToRadians(20.0f)), 1e-4f);
    Camera empty = cameraFittingBounds(Aabb{}, 40.0f);
    EXPECT_TRUE(isFinite(empty.position));
}

}  // namespace
}  // namespace penumbra
