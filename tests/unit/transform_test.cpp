// Affine transforms of normals: Affine::normal must be the normalised inverse transpose, checked
// against an inverse computed here independently (Gauss-Jordan in double) for random non-uniform
// matrices of both determinant signs; and appendScene must keep each triangle's shading normals
// on its winding's front side, mirrored or not.
#include "core/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "scene/merge.h"
#include "smooth_sphere.h"

namespace penumbra {
namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 linearPart(const Affine& a) {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = a.m[i][j];
    return m;
}

// Gauss-Jordan with partial pivoting; nothing shared with Affine's cofactor formula.
Mat3 inverse(Mat3 m) {
    Mat3 inv{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int c = 0; c < 3; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 3; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
        std::swap(m[c], m[pivot]);
        std::swap(inv[c], inv[pivot]);
        const double d = m[c][c];
        for (int k = 0; k < 3; ++k) m[c][k] /= d, inv[c][k] /= d;
        for (int r = 0; r < 3; ++r) {
            if (r == c) continue;
            const double f = m[r][c];
            for (int k = 0; k < 3; ++k) m[r][k] -= f * m[c][k], inv[r][k] -= f * inv[c][k];
        }
    }
    return inv;
}

double frobenius(const Mat3& m) {
    double s = 0;
    for (const auto& row : m)
        for (double v : row) s += v * v;
    return std::sqrt(s);
}

// normalize(inverse(M)^T n), in double.
Vec3 inverseTransposeNormal(const Mat3& inv, Vec3 n) {
    double out[3];
    for (int i = 0; i < 3; ++i) out[i] = inv[0][i] * n.x + inv[1][i] * n.y + inv[2][i] * n.z;
    const double len = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    return {float(out[0] / len), float(out[1] / len), float(out[2] / len)};
}

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return normalize(Vec3{g(rng), g(rng), g(rng)});
}

// Random well-conditioned affine maps with a general (non-uniform, sheared) linear part.
std::vector<Affine> randomAffines(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    std::vector<Affine> out;
    while (out.size() < count) {
        Affine a;
        for (auto& row : a.m)
            for (float& v : row) v = u(rng);
        const Mat3 m = linearPart(a);
        if (std::abs(a.determinant()) < 0.05f || frobenius(m) * frobenius(inverse(m)) > 30)
            continue;
        out.push_back(a);
    }
    return out;
}

void expectNear(Vec3 got, Vec3 want, float tolerance, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tolerance) << what;
    EXPECT_NEAR(got.y, want.y, tolerance) << what;
    EXPECT_NEAR(got.z, want.z, tolerance) << what;
}

TEST(AffineNormal, IsTheNormalisedInverseTransposeForRandomMatrices) {
    std::mt19937 rng(7);
    int mirrored = 0, proper = 0;
    for (const Affine& a : randomAffines(500, 11)) {
        (a.determinant() < 0 ? mirrored : proper)++;
        const Mat3 inv = inverse(linearPart(a));
        for (int k = 0; k < 4; ++k) {
            const Vec3 n = randomUnit(rng);
            expectNear(a.normal(n), inverseTransposeNormal(inv, n), 2e-5f,
                       "det " + std::to_string(a.determinant()));
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(mirrored, 100) << "too few negative determinants to test the sign fix";
    EXPECT_GT(proper, 100);
}

TEST(AffineNormal, TurnsWithARotationLikeAnyVector) {
    for (Vec3 degrees : {Vec3{0, 90, 0}, Vec3{0, 200, 0}, Vec3{30, -45, 70}, Vec3{-120, 15, 170}}) {
        const Affine r = Affine::translation({3, -1, 2}) * Affine::eulerDegrees(degrees) *
                         Affine::scaling(Vec3{2.5f});
        std::mt19937 rng(3);
        for (int k = 0; k < 8; ++k) {
            const Vec3 n = randomUnit(rng);
            expectNear(r.normal(n), normalize(r.vector(n)), 1e-5f,
                       "rotation " + std::to_string(degrees.y));
        }
    }
}

// The defining property: a normal stays perpendicular to the transformed surface's tangents, and
// it lies on the side cross(M t1, M t2) gives, times the determinant's sign (a mirror swaps the
// winding's side, which appendScene undoes by swapping the winding).
TEST(AffineNormal, StaysPerpendicularToTransformedTangents) {
    std::mt19937 rng(5);
    for (const Affine& a : randomAffines(300, 13)) {
        const Vec3 t1 = randomUnit(rng), t2 = randomUnit(rng);
        const Vec3 n = normalize(cross(t1, t2));
        if (length(cross(t1, t2)) < 0.1f) continue;
        const Vec3 nt = a.normal(n), mt1 = normalize(a.vector(t1)), mt2 = normalize(a.vector(t2));
        EXPECT_NEAR(dot(nt, mt1), 0.0f, 1e-4f);
        EXPECT_NEAR(dot(nt, mt2), 0.0f, 1e-4f);
        const float side = dot(nt, cross(mt1, mt2));
        EXPECT_EQ(side > 0, a.determinant() > 0) << "det " << a.determinant();
    }
}

// A smooth sphere placed by rotations, non-uniform scales and mirrors: every triangle's shading
// normals stay within 90 degrees of its winding's normal, which still faces outward, and equal the
// inverse transpose of the original normals.
// Arvo's centre-and-extent form: the box holds every transformed corner, and is that box (the
// tightest one) up to rounding.
TEST(TransformBounds, HoldsEveryCornerAndIsTheirBox) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> coord(-50, 50), side(0, 5);
    for (const Affine& a : randomAffines(500, 19)) {
        const Vec3 lo{coord(rng), coord(rng), coord(rng)};
        const Aabb box{lo, lo + Vec3{side(rng), side(rng), side(rng)}};
        const Aabb out = transformBounds(box, a);
        Aabb corners;
        for (int c = 0; c < 8; ++c) {
            const Vec3 p = a.point({(c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                                    (c & 4) ? box.hi.z : box.lo.z});
            corners.grow(p);
            for (int i = 0; i < 3; ++i) {
                EXPECT_LE(out.lo[i], p[i]);
                EXPECT_GE(out.hi[i], p[i]);
            }
        }
        // Rounding grows with the terms summed (entries in [-2, 2] times coordinates), not the result.
        float magnitude = 1;
        for (int i = 0; i < 3; ++i) magnitude = std::max({magnitude, std::abs(box.lo[i]), std::abs(box.hi[i])});
        const float tolerance = 1e-5f * (1 + 8 * magnitude);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(out.lo[i], corners.lo[i], tolerance);
            EXPECT_NEAR(out.hi[i], corners.hi[i], tolerance);
        }
    }
    EXPECT_TRUE(transformBounds(Aabb{}, randomAffines(1, 3)[0]).empty());
}

TEST(AppendScene, KeepsShadingNormalsOnTheFrontSideOfTheirTriangles) {
    const std::vector<Affine> transforms = {
        Affine::eulerDegrees({0, 200, 0}),
        Affine::translation({1, 2, 3}) * Affine::eulerDegrees({35, -60, 20}) *
            Affine::scaling({0.3f, 1.7f, 0.9f}),
        Affine::eulerDegrees({10, 80, -30}) * Affine::scaling({-1.2f, 0.6f, 1.0f}),
        Affine::scaling({1, 1, -1}),
    };
    for (std::size_t i = 0; i < transforms.size(); ++i) {
        const Affine& t = transforms[i];
        Scene part;
        part.materials.push_back({"m"});
        part.meshes.push_back(test::smoothSphere(Vec3{0}, 1.0f, 6, 8, 0));
        const Mesh original = part.meshes[0];
        Scene scene;
        appendScene(scene, part, t);
        const Mat3 inv = inverse(linearPart(t));
        for (std::size_t v = 0; v < original.normals.size(); ++v)
            expectNear(scene.meshes[0].normals[v], inverseTransposeNormal(inv, original.normals[v]),
                       2e-5f, "transform " + std::to_string(i));
        const Vec3 centre = t.point(Vec3{0});
        for (const SceneTriangle& tri : flattenTriangles(scene)) {
            const Vec3 ng = cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
            EXPECT_GT(dot(ng, (tri.p[0] + tri.p[1] + tri.p[2]) / 3.0f - centre), 0.0f)
                << "transform " << i << ": a front face turned inward";
            for (const Vec3& n : tri.n)
                EXPECT_GT(dot(n, ng), 0.0f)
                    << "transform " << i << ": shading normal behind its face";
            if (HasFailure()) return;
        }
    }
}

TEST(TransformCamera, MovesTheCameraWithTheWorldAndScalesItsLens) {
    Camera c;
    c.position = {0, 1, 4};
    c.lookAt = {0, 1, 0};
    c.up = {0, 1, 0};
    c.apertureRadius = 0.05f;
    c.focusDistance = 3.0f;
    const Affine t = Affine::translation({5, 0, 0}) * Affine::eulerDegrees({0, 90, 0}) *
                     Affine::scaling(Vec3{-2});
    const Camera m = transformCamera(c, t);
    expectNear(m.position, t.point(c.position), 1e-5f, "position");
    expectNear(m.lookAt, t.point(c.lookAt), 1e-5f, "look-at");
    expectNear(m.up, {0, -1, 0}, 1e-5f, "up");
    EXPECT_FLOAT_EQ(m.apertureRadius, 0.1f);
    EXPECT_FLOAT_EQ(m.focusDistance, 6.0f);
    EXPECT_FLOAT_EQ(m.fovYDegrees, c.fovYDegrees);
}

}  // namespace
}  // namespace penumbra
