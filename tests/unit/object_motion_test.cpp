// Scene-file motions (scene/object_motion.h): an object with a known path and spin is where the
// motion says at several times, through the scene file, applySceneTime and the baked meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/error.h"
#include "image/test_dir.h"
#include "scene/animation.h"
#include "scene/io/scene_json.h"
#include "scene/instances.h"
#include "scene_json_test_util.h"
#include "shared/constants.h"

namespace penumbra::test {
namespace {

// A unit quad in y = 0 around the origin, placed 2 m up, patrolling a square of side 3 m at
// 1.5 m/s (one side every 2 s) and spinning a quarter turn per second about +y.
const char* kMovingQuad = R"({
    "materials": [{"name": "m"}],
    "assets": [{"file": "quad.json", "translate": [0, 2, 0], "motion": {
        "path": [[0, 0, 0], [3, 0, 0], [3, 0, 3], [0, 0, 3]], "speed": 1.5,
        "spin": {"axis": [0, 1, 0], "degrees_per_second": 90}}}]})";

Scene movingQuad(const std::string& motion = "") {
    const TempDir dir;  // removed even when loading throws (the bad motions below)
    std::ofstream(dir / "quad.json") << R"({"materials": [{"name": "m"}],
        "quads": [{"material": "m", "corners": [[1, 0, 0], [0, 0, 0], [0, 0, 1], [1, 0, 1]]}]})";
    std::string text = kMovingQuad;
    if (!motion.empty()) {
        const std::size_t at = text.find("\"motion\"");
        text = text.substr(0, at) + "\"motion\": " + motion + "}]}";
    }
    std::ofstream(dir / "scene.json") << text;
    return loadSceneJson(dir / "scene.json");
}

// Where the quad's corner at object-space (1, 0, 0) is at `seconds`.
Vec3 cornerAt(const Scene& s, double seconds) {
    Scene moved = sceneAtTime(s, seconds);
    bakeAllInstances(moved);
    return moved.meshes.at(0).positions.at(0);
}

void expectNear(Vec3 a, Vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-4f);
    EXPECT_NEAR(a.y, b.y, 1e-4f);
    EXPECT_NEAR(a.z, b.z, 1e-4f);
}

TEST(ObjectMotion, AMovingAssetIsOneAnimatedInstance) {
    const Scene s = movingQuad();
    EXPECT_TRUE(s.meshes.empty());
    ASSERT_EQ(s.instances.size(), 1u);
    ASSERT_EQ(s.instanceAnimations.size(), 1u);
    EXPECT_TRUE(animatesGeometry(s));
}

TEST(ObjectMotion, PathAndSpinPutTheObjectWhereTheMotionSays) {
    const Scene s = movingQuad();
    // Spin R(theta) about +y maps (1, 0, 0) to (cos theta, 0, -sin theta); then +2 up, then the path.
    auto expected = [](Vec3 offset, double degrees) {
        const double r = degreesToRadians(degrees);
        return Vec3{float(std::cos(r)), 2.0f, float(-std::sin(r))} + offset;
    };
    expectNear(cornerAt(s, 0.0), expected({0, 0, 0}, 0));
    expectNear(cornerAt(s, 1.0), expected({1.5f, 0, 0}, 90));   // halfway along the first side
    expectNear(cornerAt(s, 2.0), expected({3, 0, 0}, 180));     // the second point
    expectNear(cornerAt(s, 3.0), expected({3, 0, 1.5f}, 270));
    expectNear(cornerAt(s, 7.0), expected({0, 0, 1.5f}, 270));  // on the closing side, back to the start
    expectNear(cornerAt(s, 8.0), cornerAt(s, 0.0));             // one period: 12 m at 1.5 m/s
}

TEST(ObjectMotion, BackAndForthAndOnce) {
    const Scene patrol = movingQuad(R"({"path": [[0, 0, 0], [4, 0, 0]], "speed": 2, "repeat": "back_and_forth"})");
    expectNear(cornerAt(patrol, 1.0), {3, 2, 0});
    expectNear(cornerAt(patrol, 3.0), {3, 2, 0});  // on the way back
    expectNear(cornerAt(patrol, 4.5), {2, 2, 0});  // out again
    const Scene once = movingQuad(R"({"path": [[0, 0, 0], [4, 0, 0]], "speed": 2, "repeat": "once"})");
    expectNear(cornerAt(once, 1.0), {3, 2, 0});
    expectNear(cornerAt(once, 100.0), {5, 2, 0});  // stays at the end
}

// Each entry of "instances" may move on its own; the others stay put.
TEST(ObjectMotion, InstancesMoveOneByOne) {
    const TempDir dir;
    std::ofstream(dir / "quad.json") << R"({"materials": [{"name": "m"}],
        "quads": [{"material": "m", "corners": [[1, 0, 0], [0, 0, 0], [0, 0, 1], [1, 0, 1]]}]})";
    std::ofstream(dir / "scene.json") << R"({"assets": [{"file": "quad.json", "instances": [
        {"translate": [0, 0, 0], "motion": {"path": [[0, 0, 0], [0, 0, 10]], "speed": 2, "repeat": "once"}},
        {"translate": [5, 0, 0]}]}]})";
    std::ofstream(dir / "both.json") << R"({"assets": [{"file": "quad.json", "motion": {"spin":
        {"degrees_per_second": 1}}, "instances": [{}]}]})";
    const Scene s = loadSceneJson(dir / "scene.json");
    std::string bothError;
    try {
        loadSceneJson(dir / "both.json");
    } catch (const Error& e) {
        bothError = e.what();
    }
    ASSERT_EQ(s.instances.size(), 2u);
    ASSERT_EQ(s.instanceAnimations.size(), 1u);
    const Scene later = sceneAtTime(s, 2.0);
    expectNear(later.instances[0].transform.point(Vec3{0}), {0, 0, 4});
    expectNear(later.instances[1].transform.point(Vec3{0}), {5, 0, 0});
    EXPECT_NE(bothError.find("assets[0].motion"), std::string::npos) << bothError;
}

TEST(ObjectMotion, BadMotionsNameTheProblem) {
    auto error = [](const std::string& motion) {
        try {
            movingQuad(motion);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error(R"({"path": [[0, 0, 0], [1, 0, 0]]})").find("motion: missing \"speed\""), std::string::npos);
    EXPECT_NE(error(R"({"path": [[0, 0, 0], [1, 0, 0]], "speed": 0})").find("motion.speed"), std::string::npos);
    EXPECT_NE(error(R"({"repeat": "sometimes"})").find("motion.repeat"), std::string::npos);
    EXPECT_NE(error(R"({"spin": {"axis": [0, 0, 0], "degrees_per_second": 5}})").find("spin.axis"), std::string::npos);
    EXPECT_NE(error(R"({"speed": 1, "wobble": 2})").find("motion.wobble: unknown key"), std::string::npos);
    EXPECT_NE(error(R"([1, 2])").find("expected an object"), std::string::npos);
}

}  // namespace
}  // namespace penumbra::test
