// Ray-sphere intersection (CPU reference) against analytic answers, its numerical robustness,
// self-intersection with the shaders' ray offset, and spheres in the BVH with triangles.
#include "bvh/sphere.h"

#include <bit>

#include "bvh_test_util.h"

namespace penumbra::bvh::test {
namespace {

bool hitSphere(Vec3 c, float r, Vec3 o, Vec3 d, float& t, float tMax = 1e30f) {
    return intersectSphere(toSphereVerts(c, r), Ray{o, d, tMax}, tMax, t);
}

TEST(Sphere, HitsFromOutsideAtDistanceMinusRadiusAndFromInsideAtTheExit) {
    float t = 0;
    ASSERT_TRUE(hitSphere({0, 0, -5}, 1, {0, 0, 0}, {0, 0, -1}, t));
    EXPECT_FLOAT_EQ(t, 4.0f);
    ASSERT_TRUE(hitSphere({0, 0, -5}, 1, {0, 0, -5}, {0, 1, 0}, t));  // from the centre
    EXPECT_FLOAT_EQ(t, 1.0f);
    ASSERT_TRUE(hitSphere({0, 0, 0}, 2, {1, 0, 0}, {-1, 0, 0}, t));  // inside, toward the far side
    EXPECT_FLOAT_EQ(t, 3.0f);
    // An off-centre chord: y = 0.6 crosses the unit sphere at x = +-0.8.
    ASSERT_TRUE(hitSphere({0, 0, 0}, 1, {-3, 0.6f, 0}, {1, 0, 0}, t));
    EXPECT_NEAR(t, 2.2f, 1e-6f);
    // A non-unit direction measures t in its own units.
    ASSERT_TRUE(hitSphere({0, 0, -5}, 1, {0, 0, 0}, {0, 0, -2}, t));
    EXPECT_FLOAT_EQ(t, 2.0f);
}

TEST(Sphere, MissesBehindBeyondTmaxAndBesideIt) {
    float t = 0;
    EXPECT_FALSE(hitSphere({0, 0, -5}, 1, {0, 0, 0}, {0, 0, 1}, t));           // behind
    EXPECT_FALSE(hitSphere({0, 0, -5}, 1, {0, 0, 0}, {0, 0, -1}, t, 3.9f));    // beyond tMax
    EXPECT_FALSE(hitSphere({0, 0, -5}, 1, {0, 1.001f, 0}, {0, 0, -1}, t));     // beside
    EXPECT_FALSE(hitSphere({0, 0, -5}, 1, {0, 0, 0}, {0, 0, 0}, t));           // no direction
}

// A tiny sphere far away: b^2 - ac would cancel to nothing in float; the stable form keeps t to
// a few ulps.
TEST(Sphere, SmallDistantSphereKeepsItsDigits) {
    float t = 0;
    ASSERT_TRUE(hitSphere({0, 0, -10000}, 0.01f, {0, 0.005f, 0}, {0, 0, -1}, t));
    const double exact = 10000.0 - std::sqrt(0.01 * 0.01 - 0.005 * 0.005);
    EXPECT_NEAR(t, exact, 4 * 1e4 * 0x1p-24);
}

// shaders/lib/offset.glsl, for the self-intersection test below.
Vec3 offsetRayOrigin(Vec3 p, Vec3 n) {
    Vec3 out;
    for (int a = 0; a < 3; ++a) {
        int ulps = int(256.0f * n[a]);
        int bits = std::bit_cast<int>(p[a]) + (p[a] < 0 ? -ulps : ulps);
        out[a] = std::abs(p[a]) < 1.0f / 32 ? p[a] + n[a] / 65536.0f : std::bit_cast<float>(bits);
    }
    return out;
}

// Rays leaving a sphere's surface (the hit re-projected onto the sphere, as the shader does):
// outward from the outside they never hit the sphere again; inward (a refracted ray in glass)
// they find the far side, computed here in double precision, not the point they left.
TEST(Sphere, OffsetRaysLeavingTheSurfaceDoNotHitItAgain) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int inward = 0;
    for (int i = 0; i < 20000; ++i) {
        Vec3 c{u(rng) * 10, u(rng) * 10, u(rng) * 10};
        float r = std::pow(10.0f, 1.5f * u(rng) + 0.5f);  // 0.1 to 100
        Vec3 n = randomDirection(rng);
        Vec3 p = c + n * r;
        Vec3 d = randomDirection(rng);
        float t = 0;
        if (dot(d, n) > 0) {
            EXPECT_FALSE(hitSphere(c, r, offsetRayOrigin(p, n), d, t)) << "outward ray " << i << " t " << t;
            continue;
        }
        ++inward;
        Vec3 o = offsetRayOrigin(p, -n);
        ASSERT_TRUE(hitSphere(c, r, o, d, t)) << "inward ray " << i;
        double f[3] = {double(o.x) - c.x, double(o.y) - c.y, double(o.z) - c.z};
        double fd = f[0] * d.x + f[1] * d.y + f[2] * d.z, ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
        double exit = -fd + std::sqrt(fd * fd - (ff - double(r) * r));  // d is unit
        // Float rounding of |f|^2 - r^2 (about 2^-24 (r + |c|)^2) moves a short, grazing chord's
        // end by that over the chord; a self-hit would instead give t near 0.
        const double scale = r + length(c);
        EXPECT_NEAR(t, exit, 1e-5 * scale + 2e-7 * scale * scale / exit) << "inward ray " << i;
        EXPECT_GT(t, 0.5 * exit) << "inward ray " << i;
    }
    EXPECT_GT(inward, 5000);
}

TEST(Sphere, BvhWithSpheresAndTrianglesMatchesBruteForce) {
    std::vector<Triangle> tris = randomSoup(500, 3);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Vec3> centres;
    std::vector<float> radii;
    std::vector<Aabb> boxes = boxesOf(tris);
    for (int i = 0; i < 300; ++i) {
        centres.push_back(randomPoint(rng, Aabb{Vec3(0.0f), Vec3(1.0f)}));
        radii.push_back(0.002f + 0.05f * u(rng) * u(rng));
        boxes.push_back(sphereBounds(centres.back(), radii.back()));
    }
    Bvh bvh = build(boxes);
    std::vector<shader::TriVerts> prims(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        std::uint32_t id = bvh.primOrder[i];
        prims[i] = id < tris.size() ? toTriVerts(tris[id]) : toSphereVerts(centres[id - tris.size()], radii[id - tris.size()]);
    }
    int sphereHits = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray;
        // Every other ray starts inside a sphere.
        std::size_t k = std::size_t(u(rng) * 300) % 300;
        ray.origin = i % 2 ? centres[k] + randomDirection(rng) * (0.9f * radii[k] * u(rng))
                           : randomPoint(rng, Aabb{Vec3(-0.2f), Vec3(1.2f)});
        ray.direction = randomDirection(rng);
        if (i % 5 == 0) ray.tMax = u(rng);
        Hit ref = closestHitBrute(prims, ray);
        Hit got = closestHit(bvh.nodes, prims, ray);
        ASSERT_EQ(got.triangle != PN_NO_HIT, ref.triangle != PN_NO_HIT) << "ray " << i;
        EXPECT_EQ(anyHit(bvh.nodes, prims, ray), ref.triangle != PN_NO_HIT) << "ray " << i;
        if (ref.triangle == PN_NO_HIT) continue;
        EXPECT_EQ(got.t, ref.t) << "ray " << i;
        sphereHits += isSphere(prims[ref.triangle]);
    }
    EXPECT_GT(sphereHits, 5000);
}

}  // namespace
}  // namespace penumbra::bvh::test
