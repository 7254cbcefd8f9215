// Camera paths (scene/animation.h) and the durations of --time-limit (core/duration.h).
#include <gtest/gtest.h>

#include "core/duration.h"
#include "core/error.h"
#include "scene/animation.h"
#include "scene/io/scene_json.h"

namespace penumbra {
namespace {

CameraPath threeKeys(PathInterpolation mode) {
    CameraPath p;
    p.interpolation = mode;
    p.keys = {CameraKey{0.0, Vec3{0, 0, 0}, Vec3{0, 0, -1}, 40},
              CameraKey{1.0, Vec3{2, 0, 0}, Vec3{2, 0, -1}, 60},
              CameraKey{3.0, Vec3{2, 4, 0}, Vec3{2, 4, -1}, 60}};
    return p;
}

TEST(CameraPath, PassesThroughEveryKeyAndClampsOutside) {
    for (PathInterpolation mode : {PathInterpolation::CatmullRom, PathInterpolation::Linear}) {
        const CameraPath p = threeKeys(mode);
        for (const CameraKey& k : p.keys) {
            const Camera c = cameraOnPath(p, Camera{}, k.time);
            EXPECT_NEAR(length(c.position - k.position), 0.0f, 1e-5f);
            EXPECT_NEAR(length(c.lookAt - k.lookAt), 0.0f, 1e-5f);
            EXPECT_NEAR(c.fovYDegrees, k.fovYDegrees, 1e-4f);
        }
        EXPECT_NEAR(length(cameraOnPath(p, Camera{}, -5).position - p.keys[0].position), 0.0f, 1e-6f);
        EXPECT_NEAR(length(cameraOnPath(p, Camera{}, 99).position - p.keys[2].position), 0.0f, 1e-6f);
    }
}

TEST(CameraPath, LinearMovesAtConstantSpeedWithinASegment) {
    const CameraPath p = threeKeys(PathInterpolation::Linear);
    const Camera c = cameraOnPath(p, Camera{}, 2.5);  // three quarters of the second segment
    EXPECT_NEAR(c.position.y, 3.0f, 1e-5f);
    EXPECT_NEAR(cameraOnPath(p, Camera{}, 0.25).fovYDegrees, 45.0f, 1e-4f);
}

TEST(CameraPath, CatmullRomIsContinuousWithContinuousVelocity) {
    const CameraPath p = threeKeys(PathInterpolation::CatmullRom);
    const double h = 1e-3;
    auto at = [&](double t) { return cameraOnPath(p, Camera{}, t).position; };
    // Across the key at t = 1: positions meet, and the one-sided velocities agree.
    const Vec3 vBefore = (at(1.0) - at(1.0 - h)) / float(h), vAfter = (at(1.0 + h) - at(1.0)) / float(h);
    EXPECT_LT(length(vBefore - vAfter), 0.05f * length(vBefore));
    // The tangent at key 1 is the central difference over time: ((2,4,0) - (0,0,0)) / 3.
    EXPECT_NEAR(vAfter.x, 2.0f / 3.0f, 0.02f);
    EXPECT_NEAR(vAfter.y, 4.0f / 3.0f, 0.02f);
}

TEST(CameraPath, SceneTimeMovesTheCameraAndWhatItCarries) {
    Scene s;
    s.camera.up = Vec3{0, 1, 0};
    s.cameraPath = threeKeys(PathInterpolation::Linear);
    Light torch;
    torch.moves = true;
    torch.position = Vec3{0, -0.1f, 0};
    s.lights.push_back(torch);
    EXPECT_TRUE(isAnimated(s));
    const Scene later = sceneAtTime(s, 1.0);
    EXPECT_NEAR(later.camera.position.x, 2.0f, 1e-5f);
    EXPECT_NEAR(later.lights[0].position.x, 2.0f, 1e-5f);
    EXPECT_NEAR(later.lights[0].position.y, -0.1f, 1e-5f);
}

TEST(CameraPath, BadKeysNameTheKey) {
    CameraPath p = threeKeys(PathInterpolation::Linear);
    p.keys[2].time = 1.0;
    try {
        validateCameraPath(p);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("key 2"), std::string::npos) << e.what();
    }
    p = threeKeys(PathInterpolation::Linear);
    p.keys[0].lookAt = p.keys[0].position;
    EXPECT_THROW(validateCameraPath(p), Error);
}

TEST(CameraPath, ReadFromASceneFile) {
    const char* text = R"({"materials": [{"name": "m"}], "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "m"}],
        "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 30},
        "camera_path": {"interpolation": "linear",
                        "keys": [{"time": 0, "position": [0, 0, 5], "look_at": [0, 0, 0]},
                                 {"time": 2, "position": [4, 0, 5], "look_at": [0, 0, 0], "fov": 50}]}})";
    const Scene s = loadSceneJsonFromText(text, ".", "path.json");
    ASSERT_EQ(s.cameraPath.keys.size(), 2u);
    EXPECT_EQ(s.cameraPath.keys[0].fovYDegrees, 30.0f);  // a key without a fov takes the camera's
    EXPECT_NEAR(sceneAtTime(s, 1.0).camera.position.x, 2.0f, 1e-5f);
    EXPECT_NEAR(sceneAtTime(s, 1.0).camera.fovYDegrees, 40.0f, 1e-4f);
}

TEST(Duration, ReadsWhatPeopleType) {
    EXPECT_EQ(parseDuration("90", "--t"), 90.0);
    EXPECT_EQ(parseDuration("2.5", "--t"), 2.5);
    EXPECT_EQ(parseDuration("90s", "--t"), 90.0);
    EXPECT_EQ(parseDuration("2m", "--t"), 120.0);
    EXPECT_EQ(parseDuration("1h30m", "--t"), 5400.0);
    EXPECT_EQ(parseDuration("1m30s", "--t"), 90.0);
    EXPECT_EQ(parseDuration("1.5h", "--t"), 5400.0);
}

TEST(Duration, RefusesTheRestNamingTheFlag) {
    for (const char* bad : {"", "0", "-5", "m", "5x", "30s1m", "1m1m", "1m30", "90 5", "1e400", "nan", "2y", "9000h"}) {
        try {
            parseDuration(bad, "--time-limit");
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const UsageError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--time-limit", 0), 0u) << e.what();
        }
    }
}

}  // namespace
}  // namespace penumbra

#include "scene/node_animation.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

// Rotation keys: halfway between 0 and 90 degrees about +y is 45 degrees, whichever sign the
// second key's quaternion has (q and -q are one rotation; slerp takes the shorter arc).
TEST(NodeAnimation, RotationsInterpolateAlongTheShorterArc) {
    const float s = std::sin(0.25f * kPiF), c = std::cos(0.25f * kPiF);  // 90 deg about y
    for (float sign : {1.0f, -1.0f}) {
        Track track;
        track.times = {0.0f, 2.0f};
        track.values = {{0, 0, 0, 1}, {0, sign * s, 0, sign * c}};
        const KeyValue q = sampleTrack(track, 1.0, true);
        const Affine r = trsTransform(Vec3{0}, q, Vec3{1});
        const Vec3 x = r.vector({1, 0, 0});
        const float k = std::sqrt(0.5f);
        EXPECT_NEAR(x.x, k, 1e-5f);
        EXPECT_NEAR(x.z, -k, 1e-5f) << "sign " << sign;
    }
}

TEST(NodeAnimation, ChainsComposeParentFirst) {
    NodeMotion parent, child;
    parent.fixed = Affine::eulerDegrees({0, 90, 0});
    child.trs = true;
    child.translationTrack.times = {0.0f, 1.0f};
    child.translationTrack.values = {{0, 0, 0, 0}, {1, 0, 0, 0}};
    const Vec3 p = chainTransform({parent, child}, 1.0).point(Vec3{0});
    EXPECT_NEAR(p.x, 0.0f, 1e-5f);
    EXPECT_NEAR(p.z, -1.0f, 1e-5f);  // the child's +x, turned 90 degrees about +y by the parent
    Track bad = child.translationTrack;
    bad.times = {1.0f, 1.0f};
    EXPECT_THROW(validateTrack(bad, "test"), Error);
}

}  // namespace
}  // namespace penumbra
