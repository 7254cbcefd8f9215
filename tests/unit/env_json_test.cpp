// The scene file's "environment" and "angular_radius": what they set, and one-line errors that
// say where.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "image/write.h"
#include "scene/environment.h"
#include "scene/io/scene_json.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

const char* kFloor = R"("meshes": [{"material": "m", "positions": [0,0,0, 1,0,0, 0,0,1], "indices": [0,1,2]}],
                       "materials": [{"name": "m"}])";

Scene parse(const std::string& body, const std::filesystem::path& dir = ".") {
    return loadSceneJsonFromText("{" + std::string(kFloor) + ", " + body + "}", dir, "env.json", nullptr);
}

std::string errorOf(const std::string& body) {
    try {
        parse(body);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(EnvJson, SkyMakesAMapAndASunThatFollowRotationAndIntensity) {
    Scene s = parse(R"("environment": {"sky": {"sun_elevation": 30, "sun_azimuth": 0, "turbidity": 4, "sun_radius": 1.5},
                                       "intensity": 2, "rotation": 90})");
    ASSERT_TRUE(s.environment.map);
    ASSERT_TRUE(s.environment.sun);
    EXPECT_EQ(s.environment.intensity, 2.0f);
    EXPECT_NEAR(s.environment.sun->angularRadius, degreesToRadians(1.5f), 1e-6f);
    std::vector<Light> lights = distantLights(s.environment);
    ASSERT_EQ(lights.size(), 1u);
    // Azimuth 0 is -z; turned 90 degrees about +y it is -x. The light travels away from the sun.
    EXPECT_NEAR(lights[0].direction.x, std::cos(degreesToRadians(30.0f)), 1e-5f);
    EXPECT_NEAR(lights[0].direction.y, -0.5f, 1e-5f);
    EXPECT_NEAR(lights[0].direction.z, 0.0f, 1e-5f);
    EXPECT_NEAR(lights[0].intensity, 2 * s.environment.sun->intensity, 1e-4f);
}

TEST(EnvJson, FileIsRelativeToTheSceneFile) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "penumbra_env_json_test";
    std::filesystem::create_directories(dir);
    writeImage(dir / "sky.exr", ImageRgb(4, 2, Vec3{0.25f}), {});
    Scene s = parse(R"("environment": {"file": "sky.exr"})", dir);
    ASSERT_TRUE(s.environment.map);
    EXPECT_EQ(s.environment.map->width, 4);
    EXPECT_EQ(s.environment.map->radiance[5].y, 0.25f);
    EXPECT_FALSE(s.environment.sun);
}

TEST(EnvJson, AngularRadiusIsForDirectionalLightsOnly) {
    Scene s = parse(R"("lights": [{"type": "directional", "direction": [0,-1,0], "angular_radius": 10}])");
    EXPECT_NEAR(s.lights[0].angularRadius, degreesToRadians(10.0f), 1e-6f);
    EXPECT_NE(errorOf(R"("lights": [{"type": "point", "angular_radius": 1}])").find("lights[0].angular_radius"), std::string::npos);
    EXPECT_NE(errorOf(R"("lights": [{"type": "directional", "angular_radius": 60}])").find("between 0 and 45"), std::string::npos);
}

TEST(EnvJson, BadEnvironmentsSayWhere) {
    EXPECT_NE(errorOf(R"("environment": {"file": "a.hdr", "sky": {}})").find("not both"), std::string::npos);
    EXPECT_NE(errorOf(R"("environment": {"sky": {"turbidity": 40}})").find("environment.sky.turbidity"), std::string::npos);
    EXPECT_NE(errorOf(R"("environment": {"intensity": -1})").find("environment.intensity"), std::string::npos);
    EXPECT_NE(errorOf(R"("environment": {"file": "missing.hdr"})").find("environment"), std::string::npos);
    EXPECT_NE(errorOf(R"("environment": [1])").find("expected an object"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
