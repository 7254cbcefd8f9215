// Dragging the caffeine molecule (interact/group_drag.h): a press on any atom of the selected group
// grabs the whole group; dragging moves every atom by the same offset so the grabbed point stays
// under the cursor, and a Shift drag turns the group about the vertical through its pivot.
#include <gtest/gtest.h>

#include "interact/group_drag.h"
#include "interact/object_drag.h"
#include "render/gpu_scene.h"
#include "render/picking.h"
#include "scene/presets/presets.h"
#include "scene/sphere_groups.h"

namespace penumbra::viewer {
namespace {

constexpr std::uint32_t kWidth = 320, kHeight = 240;

TEST(GroupDrag, APressOnAnAtomGrabsTheGroupAndADragMovesEveryAtomAlike) {
    Scene scene = makePreset("caffeine");
    const SceneArrays arrays = buildSceneArrays(scene);
    Camera camera = scene.camera;
    camera.lookAt = sphereGroupPivot(scene, 0);
    // Find a pixel near the centre that shows an atom.
    std::optional<GroupDrag> drag;
    float px = 0, py = 0;
    for (int r = 0; r < 40 && !drag; ++r)
        for (int dx = -r; dx <= r && !drag; ++dx) {
            px = kWidth / 2.0f + float(dx);
            py = kHeight / 2.0f + float(r);
            drag = grabSphereGroup(scene, arrays, camera, kWidth, kHeight, px, py, 0, false);
        }
    ASSERT_TRUE(drag.has_value()) << "no atom near the image centre";
    EXPECT_FALSE(grabSphereGroup(scene, arrays, camera, kWidth, kHeight, px, py, 1, false)) << "no such group";
    EXPECT_FALSE(grabSphereGroup(scene, arrays, camera, kWidth, kHeight, 2.0f, float(kHeight) - 2.0f, 0, false))
        << "the coffee is not the molecule";

    const Scene before = scene;
    const Vec3 grabbed = sphereGroupPivot(scene, 0) + drag->grabbedFromPivot;
    ASSERT_TRUE(followCursor(*drag, scene, camera, kWidth, kHeight, px + 30, py - 20));
    const Vec3 offset = scene.spheres[0].center - before.spheres[0].center;
    EXPECT_GT(length(offset), 0.01f);
    for (std::uint32_t i : scene.sphereGroups[0].spheres)
        EXPECT_LT(length(scene.spheres[i].center - before.spheres[i].center - offset), 1e-5f) << "atom " << i;
    EXPECT_EQ(scene.spheres.back().center, before.spheres.back().center) << "the lamp stays";
    // The grabbed point moved as dragOffset says it must to be under the cursor again.
    EXPECT_LT(length(offset - dragOffset(camera, kWidth, kHeight, grabbed, px + 30, py - 20)), 1e-5f);
    EXPECT_FALSE(followCursor(*drag, scene, camera, kWidth, kHeight, px + 30, py - 20)) << "a still cursor moves nothing";
}

TEST(GroupDrag, AShiftDragTurnsTheGroupAboutTheVerticalThroughItsPivot) {
    Scene scene = makePreset("caffeine");
    const Camera camera = scene.camera;
    GroupDrag drag{0, Vec3{0}, true, 100.0f};
    const Scene before = scene;
    const Vec3 pivot = sphereGroupPivot(scene, 0);
    ASSERT_TRUE(followCursor(drag, scene, camera, kWidth, kHeight, 100.0f + kWidth / 4.0f, 50.0f));
    // A quarter of the window's width: a quarter turn.
    const Affine quarter = Affine::eulerDegrees({0, 90, 0});
    for (std::uint32_t i : scene.sphereGroups[0].spheres) {
        const Vec3 expected = pivot + quarter.vector(before.spheres[i].center - pivot);
        EXPECT_LT(length(scene.spheres[i].center - expected), 1e-5f) << "atom " << i;
    }
}

}  // namespace
}  // namespace penumbra::viewer
