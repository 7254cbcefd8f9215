// Sphere lights on the host: which lights become spheres, their radiance, and the table light
// sampling picks from (probabilities in proportion to power, a cdf that ends at exactly 1).
#include <gtest/gtest.h>

#include <algorithm>

#include "bvh/sphere.h"
#include "render/gpu_scene.h"
#include "scene/presets/mesh_builder.h"
#include "shared/constants.h"

namespace penumbra {
namespace {


TEST(SphereLightTable, PointLightsWithRadiusBecomeSpheresAndEveryLightIsPickedByPower) {
    Scene s;
    s.name = "lights";
    std::uint32_t grey = addMaterial(s, "grey", Vec3{0.5f});
    std::uint32_t lamp = addMaterial(s, "lamp", Vec3{0}, Vec3{2.0f});
    Mesh floor;
    floor.material = grey;
    addQuad(floor, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5});
    s.meshes.push_back(floor);
    s.spheres.push_back({{0, 1, 0}, 0.5f, lamp});
    s.spheres.push_back({{2, 1, 0}, 1.0f, lamp});
    s.spheres.push_back({{4, 1, 0}, 1.0f, grey});  // not a light
    Light soft;
    soft.position = {0, 3, 0};
    soft.intensity = 3.0f;
    soft.radius = 0.25f;
    Light spot = soft;
    spot.type = LightType::Spot;
    spot.outerConeRadians = 0.5f;
    Light hard;  // radius 0: stays punctual
    hard.position = {1, 3, 0};
    s.lights = {soft, spot, hard};

    SceneArrays a = buildSceneArrays(s);
    EXPECT_EQ(a.punctual.size(), 1u);
    EXPECT_EQ(a.sphereCount, 4u);
    ASSERT_EQ(a.materials.size(), s.materials.size() + 1);
    const float pointRadiance = float(3.0 / (kPi * 0.25 * 0.25));
    EXPECT_FLOAT_EQ(a.materials.back().emission.x, pointRadiance);
    ASSERT_EQ(a.sphereLights.size(), 4u);

    for (std::size_t i = 0; i < 4; ++i) {
        const shader::SphereLight& l = a.sphereLights[i];
        if (i < 3) {
            // Emissive spheres live in the BVH, and their slot knows its light (for MIS on hits).
            ASSERT_LT(l.primitive, a.triVerts.size());
            EXPECT_TRUE(bvh::isSphere(a.triVerts[l.primitive]));
            EXPECT_EQ(a.triVerts[l.primitive].v0, l.center);
            EXPECT_EQ(a.triVerts[l.primitive].e1.x, l.radius);
            const std::uint32_t ref = a.triAttribs[l.primitive].lightIndex;
            ASSERT_LT(ref, a.lightRefs.size());
            EXPECT_EQ(a.lightRefs[ref].type, PN_LIGHTREF_SPHERE);
            EXPECT_EQ(a.lightRefs[ref].index, i);
        } else {
            EXPECT_EQ(l.primitive, PN_NO_HIT);  // the spot light has no geometry
            EXPECT_FLOAT_EQ(l.cosOuter, std::cos(0.5f));
        }
    }
    // Every sphere light is one leaf of the light tree.
    EXPECT_EQ(std::count_if(a.lightRefs.begin(), a.lightRefs.end(),
                            [](const shader::LightRef& r) { return r.type == PN_LIGHTREF_SPHERE; }),
              4);
    // The non-emissive sphere is geometry only.
    int greySpheres = 0;
    for (std::size_t i = 0; i < a.triVerts.size(); ++i)
        if (bvh::isSphere(a.triVerts[i]) && a.triAttribs[i].materialId == grey) {
            ++greySpheres;
            EXPECT_EQ(a.triAttribs[i].lightIndex, PN_NO_LIGHT);
        }
    EXPECT_EQ(greySpheres, 1);
}

}  // namespace
}  // namespace penumbra
