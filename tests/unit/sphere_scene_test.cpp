// Spheres, quads and the thin-lens camera in the scene model and scene files, and the caffeine
// preset's data.
#include <gtest/gtest.h>

#include "scene_json_test_util.h"

#include <map>

#include "core/error.h"
#include "scene/io/scene_json.h"
#include "scene/merge.h"
#include "scene/presets/presets.h"
#include "scene/sphere_groups.h"

namespace penumbra {
namespace {

Scene parse(const std::string& text, SceneFileSettings* settings = nullptr) { return test::parseSceneText(text, settings); }

std::string errorOf(const std::string& text) { return test::sceneTextError(text); }

const char* kSpheresJson = R"({
  "materials": [{"name": "red", "albedo": [0.8, 0.1, 0.1]}, {"name": "lamp", "emission": [5, 5, 5]}],
  "spheres": [{"center": [0, 1, 0], "radius": 0.5, "material": "red"},
              {"center": [2, 3, 1], "radius": 0.25, "material": "lamp"}],
  "quads": [{"name": "floor", "material": "red", "corners": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]}],
  "camera": {"position": [0, 1, 5], "look_at": [0, 1, 0], "aperture": 0.02, "focus_distance": 4.5}
})";

TEST(SphereScene, JsonReadsSpheresQuadsAndTheLens) {
    Scene s = parse(kSpheresJson);
    ASSERT_EQ(s.spheres.size(), 2u);
    EXPECT_EQ(s.spheres[1].center, (Vec3{2, 3, 1}));
    EXPECT_FLOAT_EQ(s.spheres[1].radius, 0.25f);
    EXPECT_EQ(s.materials[s.spheres[1].material].name, "lamp");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].triangleCount(), 2u);
    EXPECT_FLOAT_EQ(s.camera.apertureRadius, 0.02f);
    EXPECT_FLOAT_EQ(s.camera.focusDistance, 4.5f);
    // Bounds cover the spheres as well as the mesh.
    EXPECT_FLOAT_EQ(s.bounds().hi.y, 3.25f);
    EXPECT_FLOAT_EQ(s.bounds().hi.x, 2.25f);
    // The quad faces up: its first triangle's winding is counter-clockwise seen from +y.
    const Mesh& q = s.meshes[0];
    Vec3 n = cross(q.positions[q.indices[1]] - q.positions[q.indices[0]], q.positions[q.indices[2]] - q.positions[q.indices[0]]);
    EXPECT_GT(n.y, 0);
}

TEST(SphereScene, SpheresAloneAreEnoughGeometry) {
    Scene s = parse(R"({"materials": [{"name": "m"}], "spheres": [{"center": [0, 0, -3], "radius": 1, "material": "m"}]})");
    EXPECT_EQ(s.spheres.size(), 1u);
}

TEST(SphereScene, BadSpheresAndQuadsSayWhere) {
    const std::string base = R"({"materials": [{"name": "m"}], )";
    EXPECT_NE(errorOf(base + R"("spheres": [{"center": [0, 0, 0], "radius": 0, "material": "m"}]})").find("spheres[0].radius"),
              std::string::npos);
    EXPECT_NE(errorOf(base + R"("spheres": [{"center": [0, 0], "radius": 1, "material": "m"}]})").find("spheres[0].center"),
              std::string::npos);
    EXPECT_NE(errorOf(base + R"("spheres": [{"center": [0, 0, 0], "radius": 1, "material": "x"}]})").find("no material named 'x'"),
              std::string::npos);
    EXPECT_NE(errorOf(base + R"("quads": [{"material": "m", "corners": [[0, 0, 0], [1, 0, 0], [1, 1, 0]]}]})").find("quads[0].corners"),
              std::string::npos);
    EXPECT_NE(errorOf(base + R"("spheres": [{"center": [0, 0, 0], "radius": 1, "material": "m"}], "camera": {"aperture": -1}})")
                  .find("camera.aperture"),
              std::string::npos);
}

TEST(SphereScene, ValidateRejectsBadSpheres) {
    Scene s = parse(kSpheresJson);
    s.spheres[0].radius = -1;
    EXPECT_THROW(s.validate(), Error);
    s = parse(kSpheresJson);
    s.spheres[0].material = 7;
    EXPECT_THROW(s.validate(), Error);
    s = parse(kSpheresJson);
    s.spheres[0].center.x = std::nanf("");
    EXPECT_THROW(s.validate(), Error);
}

TEST(SphereScene, ExportRoundTripKeepsSpheresAndTheLens) {
    Scene s = parse(kSpheresJson);
    Scene back = parse(sceneToJson(s));
    ASSERT_EQ(back.spheres.size(), s.spheres.size());
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        EXPECT_EQ(back.spheres[i].center, s.spheres[i].center);
        EXPECT_EQ(back.spheres[i].radius, s.spheres[i].radius);
        EXPECT_EQ(back.materials[back.spheres[i].material].name, s.materials[s.spheres[i].material].name);
    }
    EXPECT_EQ(back.camera.apertureRadius, s.camera.apertureRadius);
    EXPECT_EQ(back.camera.focusDistance, s.camera.focusDistance);
}

TEST(SphereScene, MergingMovesAndScalesSpheresAndRenumbersTheirMaterials) {
    Scene into = parse(kSpheresJson);
    Scene part = parse(kSpheresJson);
    const std::size_t materials = into.materials.size();
    appendScene(into, part, Affine::translation({10, 0, 0}) * Affine::scaling(Vec3{2}));
    ASSERT_EQ(into.spheres.size(), 4u);
    EXPECT_EQ(into.spheres[2].center, (Vec3{10, 2, 0}));
    EXPECT_FLOAT_EQ(into.spheres[2].radius, 1.0f);
    EXPECT_EQ(into.spheres[3].material, part.spheres[1].material + materials);
    into.validate();
}

TEST(SphereScene, FocusDistanceDefaultsToTheLookAtDistance) {
    Camera c;
    c.position = {0, 0, 3};
    c.lookAt = {0, 0, -1};
    EXPECT_FLOAT_EQ(effectiveFocusDistance(c), 4.0f);
    c.focusDistance = 2.5f;
    EXPECT_FLOAT_EQ(effectiveFocusDistance(c), 2.5f);
    c.apertureRadius = -0.1f;
    EXPECT_THROW(validateCamera(c), UsageError);
}

// The preset's atoms: the formula C8H10N4O2, and chemically sensible geometry (each hydrogen
// 1.09 angstrom from exactly one heavy atom; no two atoms closer than a bond), which catches a
// mistyped coordinate.
TEST(Caffeine, PresetHasTheMoleculesAtomsAtBondingDistances) {
    Scene s = makePreset("caffeine");
    s.validate();
    std::map<std::string, int> count;
    std::vector<std::pair<std::string, Vec3>> atoms;
    for (const Sphere& sphere : s.spheres) {
        const std::string& name = s.materials[sphere.material].name;
        if (name == "lamp") continue;
        ++count[name];
        atoms.emplace_back(name, sphere.center / 0.1f);  // back to angstrom
    }
    EXPECT_EQ(count["carbon"], 8);
    EXPECT_EQ(count["hydrogen"], 10);
    EXPECT_EQ(count["nitrogen"], 4);
    EXPECT_EQ(count["oxygen"], 2);
    for (std::size_t i = 0; i < atoms.size(); ++i) {
        int bonded = 0;
        for (std::size_t j = 0; j < atoms.size(); ++j) {
            if (i == j) continue;
            const float d = length(atoms[i].second - atoms[j].second);
            EXPECT_GT(d, 1.0f) << "atoms " << i << " and " << j;
            if (atoms[i].first == "hydrogen" && atoms[j].first != "hydrogen" && d < 1.2f) {
                EXPECT_NEAR(d, 1.09f, 0.03f);
                ++bonded;
            }
        }
        if (atoms[i].first == "hydrogen") {
            EXPECT_EQ(bonded, 1) << "hydrogen " << i;
        }
    }
    EXPECT_GT(s.camera.apertureRadius, 0.0f);
    // The camera is focused on the molecule: the focus distance is the distance to its centre.
    EXPECT_NEAR(s.camera.focusDistance, length(s.camera.lookAt - s.camera.position), 1e-5f);
}

// The molecule turns as one: every atom's centre rotates rigidly about the group's pivot (the
// mean of the centres), which stays put; distances between atoms, radii and the lamp (not in the
// group) are unchanged; and a move shifts every atom by the same offset.
TEST(Caffeine, TheMoleculeTurnsAndMovesAsOneObject) {
    Scene s = makePreset("caffeine");
    ASSERT_EQ(s.sphereGroups.size(), 1u);
    ASSERT_EQ(s.sphereGroups[0].spheres.size(), 24u);
    const std::uint32_t lamp = static_cast<std::uint32_t>(s.spheres.size() - 1);
    EXPECT_FALSE(sphereGroupOf(s, lamp).has_value());
    for (std::uint32_t i = 0; i < 24; ++i) EXPECT_EQ(sphereGroupOf(s, i), std::optional<std::uint32_t>(0));

    const Scene before = s;
    const Vec3 pivot = sphereGroupPivot(s, 0);
    const Affine turn = Affine::eulerDegrees({20, 75, -10});
    turnSphereGroup(s, 0, turn);
    EXPECT_LT(length(sphereGroupPivot(s, 0) - pivot), 1e-5f);
    for (std::uint32_t i = 0; i < 24; ++i) {
        const Vec3 expected = pivot + turn.vector(before.spheres[i].center - pivot);
        EXPECT_LT(length(s.spheres[i].center - expected), 1e-5f) << "atom " << i;
        EXPECT_EQ(s.spheres[i].radius, before.spheres[i].radius);
        for (std::uint32_t j = 0; j < i; ++j)
            EXPECT_NEAR(length(s.spheres[i].center - s.spheres[j].center),
                        length(before.spheres[i].center - before.spheres[j].center), 1e-5f);
    }
    EXPECT_EQ(s.spheres[lamp].center, before.spheres[lamp].center);
    // Some atom really moved (a turn that did nothing would pass the checks above).
    float moved = 0;
    for (std::uint32_t i = 0; i < 24; ++i) moved = std::max(moved, length(s.spheres[i].center - before.spheres[i].center));
    EXPECT_GT(moved, 0.1f);

    const Scene turned = s;
    moveSphereGroup(s, 0, {0.5f, -0.25f, 1.0f});
    for (std::uint32_t i = 0; i < 24; ++i)
        EXPECT_LT(length(s.spheres[i].center - (turned.spheres[i].center + Vec3{0.5f, -0.25f, 1.0f})), 1e-6f);
    EXPECT_EQ(s.spheres[lamp].center, before.spheres[lamp].center);
}

TEST(SphereGroups, ValidationRefusesMissingAndSharedSpheres) {
    Scene s = makePreset("caffeine");
    s.sphereGroups.push_back({"bad", {999}});
    EXPECT_THROW(s.validate(), Error);
    s.sphereGroups.back().spheres = {0};  // already in the molecule
    EXPECT_THROW(s.validate(), Error);
    s.sphereGroups.back().spheres = {static_cast<std::uint32_t>(s.spheres.size() - 1)};  // the lamp: free
    EXPECT_NO_THROW(s.validate());
}

// appendScene renumbers a part's groups after the spheres already there.
TEST(SphereGroups, AppendingAScenePlacesItsGroupsAfterTheSpheresBefore) {
    Scene into = makePreset("caffeine");
    const std::size_t first = into.spheres.size();
    appendScene(into, makePreset("caffeine"), Affine::translation({3, 0, 0}));
    ASSERT_EQ(into.sphereGroups.size(), 2u);
    EXPECT_EQ(into.sphereGroups[1].spheres.front(), first);
    EXPECT_NO_THROW(into.validate());
}

}  // namespace
}  // namespace penumbra
