#include "interact/group_drag.h"

#include "interact/object_drag.h"
#include "render/picking.h"
#include "scene/sphere_groups.h"

namespace penumbra::viewer {

std::optional<GroupDrag> grabSphereGroup(const Scene& scene, const SceneArrays& arrays, const Camera& camera,
                                         std::uint32_t width, std::uint32_t height, float x, float y,
                                         std::uint32_t selected, bool turning) {
    if (selected >= scene.sphereGroups.size() || width == 0 || height == 0) return std::nullopt;
    const Pick pick = pickPixel(arrays, camera, width, height, x, y);
    if (!isObject(scene, pick.object) || pick.object < scene.meshes.size() || !(pick.depth > 0)) return std::nullopt;
    if (sphereGroupOf(scene, pick.object - scene.meshes.size()) != selected) return std::nullopt;
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 direction = pixelRayDirection(camera, width, height, x, y);
    const Vec3 grabbed = camera.position + direction * (pick.depth / dot(direction, forward));
    return GroupDrag{selected, grabbed - sphereGroupPivot(scene, selected), turning, x};
}

bool followCursor(GroupDrag& drag, Scene& scene, const Camera& camera, std::uint32_t width, std::uint32_t height,
                  float x, float y) {
    if (drag.group >= scene.sphereGroups.size() || width == 0 || height == 0) return false;
    if (drag.turning) {
        const float dx = x - drag.turnedAtX;
        if (dx == 0) return false;
        drag.turnedAtX = x;
        const Affine turn = Affine::eulerDegrees({0, dragTurnDegrees(dx, width), 0});
        turnSphereGroup(scene, drag.group, turn);
        drag.grabbedFromPivot = turn.vector(drag.grabbedFromPivot);
        return true;
    }
    const Vec3 grabbed = sphereGroupPivot(scene, drag.group) + drag.grabbedFromPivot;
    const Vec3 offset = dragOffset(camera, width, height, grabbed, x, y);
    // As for instances: below a hundredth of a pixel, nothing moved.
    if (!(length(offset) > 1e-5f * length(grabbed - camera.position))) return false;
    moveSphereGroup(scene, drag.group, offset);
    return true;
}

}  // namespace penumbra::viewer
