// The viewer's light sliders on scene data (scene/light_edit.h): which lights are listed, how their
// values read and write back, and the clamping that keeps every edit renderable.
#include <gtest/gtest.h>

#include "scene/light_edit.h"
#include "scene/presets/presets.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

TEST(LightEdit, ListsPunctualLightsAndEmissiveSpheresButNotTheTorch) {
    Scene s = makePreset("caffeine");  // one lamp sphere, no punctual light
    std::vector<EditableLight> lights = editableLights(s);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights[0].kind, EditableLight::Kind::EmissiveSphere);
    EXPECT_EQ(lights[0].index, s.spheres.size() - 1);
    EXPECT_EQ(lightName(s, lights[0]), "'lamp' sphere 24");
    Light torch;
    torch.moves = true;
    s.lights.push_back(torch);
    EXPECT_EQ(editableLights(s).size(), 1u);
}

TEST(LightEdit, AnEmissiveSpheresColourAndIntensitySplitItsEmission) {
    Scene s = makePreset("caffeine");
    const EditableLight lamp = editableLights(s)[0];
    LightParams p = lightParams(s, lamp);
    EXPECT_FLOAT_EQ(p.intensity, 60.0f);  // the lamp's emission (60, 55, 48)
    EXPECT_FLOAT_EQ(p.color.y, 55.0f / 60.0f);
    EXPECT_FLOAT_EQ(p.radius, 0.3f);
    p.intensity = 10;
    p.color = {1, 0.5f, -3};  // a negative channel clamps to 0
    p.radius = -1;            // a sphere keeps a size
    p.position = {1, 2, 3};
    setLightParams(s, lamp, p);
    const Sphere& sphere = s.spheres[lamp.index];
    EXPECT_EQ(s.materials[sphere.material].emission, (Vec3{10, 5, 0}));
    EXPECT_GT(sphere.radius, 0.0f);
    EXPECT_EQ(sphere.center, (Vec3{1, 2, 3}));
    EXPECT_NO_THROW(s.validate());
}

TEST(LightEdit, ASpotsAngleKeepsItsInnerConeInside) {
    Scene s;
    s.materials.push_back({"m", Vec3{0.5f}});
    Light spot;
    spot.type = LightType::Spot;
    spot.outerConeRadians = degreesToRadians(40.0f);
    spot.innerConeRadians = degreesToRadians(30.0f);
    s.lights.push_back(spot);
    const EditableLight light = editableLights(s).at(0);
    LightParams p = lightParams(s, light);
    EXPECT_TRUE(p.isSpot);
    EXPECT_NEAR(p.spotDegrees, 40.0f, 1e-4f);
    p.spotDegrees = 20;
    setLightParams(s, light, p);
    EXPECT_NEAR(radiansToDegrees(s.lights[0].outerConeRadians), 20.0f, 1e-4f);
    EXPECT_NEAR(radiansToDegrees(s.lights[0].innerConeRadians), 15.0f, 1e-4f);  // 3/4 of it, as before
    p.spotDegrees = 500;  // at most a hemisphere
    setLightParams(s, light, p);
    EXPECT_NEAR(radiansToDegrees(s.lights[0].outerConeRadians), 90.0f, 1e-3f);
}

TEST(LightEdit, ADirectionalLightHasNoPositionAndItsRadiusIsAnAngle) {
    Scene s;
    Light sun;
    sun.type = LightType::Directional;
    sun.angularRadius = 0.01f;
    s.lights.push_back(sun);
    const EditableLight light = editableLights(s).at(0);
    LightParams p = lightParams(s, light);
    EXPECT_FALSE(p.hasPosition);
    EXPECT_FLOAT_EQ(p.radius, 0.01f);
    p.radius = 5;  // clamps to the largest disk the sampler takes
    setLightParams(s, light, p);
    EXPECT_FLOAT_EQ(s.lights[0].angularRadius, kMaxAngularRadius);
}

}  // namespace
}  // namespace penumbra
