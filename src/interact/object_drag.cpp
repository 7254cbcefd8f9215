#include "interact/object_drag.h"

#include "core/aabb.h"
#include "render/picking.h"
#include "scene/objects.h"

namespace penumbra::viewer {
namespace {

Vec3 viewForward(const Camera& camera) { return normalize(camera.lookAt - camera.position); }

// The point on the primary ray through (x, y) at linear depth `depth`.
Vec3 pointAtDepth(const Camera& camera, std::uint32_t width, std::uint32_t height, float x, float y, float depth) {
    const Vec3 direction = pixelRayDirection(camera, width, height, x, y);
    return camera.position + direction * (depth / dot(direction, viewForward(camera)));
}

}  // namespace

std::optional<ObjectDrag> startObjectDrag(std::uint32_t instance, const Affine& objectToWorld, const Camera& camera,
                                          std::uint32_t width, std::uint32_t height, float x, float y, float depth) {
    if (!(depth > 0) || width == 0 || height == 0) return std::nullopt;
    const Vec3 grabbed = pointAtDepth(camera, width, height, x, y, depth);
    return ObjectDrag{instance, objectToWorld.inverse().point(grabbed)};
}

Vec3 dragOffset(const Camera& camera, std::uint32_t width, std::uint32_t height, Vec3 grabbed, float x, float y) {
    const float depth = dot(grabbed - camera.position, viewForward(camera));
    if (!(depth > 0) || width == 0 || height == 0) return Vec3{0};
    return pointAtDepth(camera, width, height, x, y, depth) - grabbed;
}

float dragTurnDegrees(float dxPixels, std::uint32_t width) {
    return width == 0 ? 0.0f : dxPixels * (kTurnDegreesPerWindowWidth / float(width));
}

InstanceTurn turnAboutCentre(const Affine& objectToWorld, Vec3 centreLocal, float yawDegrees) {
    // moveInstance keeps the origin o and turns the linear part L: the centre o + L c would go to
    // o + R L c. Moving the origin by d - R d (d = L c) puts it back at o + d.
    const Vec3 d = objectToWorld.vector(centreLocal);
    return {d - Affine::eulerDegrees({0, yawDegrees, 0}).vector(d), yawDegrees};
}

Vec3 prototypeCentre(const Scene& scene, std::uint32_t prototype) {
    if (prototype >= scene.prototypes.size()) return Vec3{0};
    Aabb box;
    for (const Mesh& mesh : scene.prototypes[prototype].meshes)
        for (const Vec3& p : mesh.positions) box.grow(p);
    return box.empty() ? Vec3{0} : (box.lo + box.hi) * 0.5f;
}

std::optional<ObjectDrag> grabInstance(const Scene& scene, const SceneArrays& arrays, const Camera& camera,
                                       std::uint32_t width, std::uint32_t height, float x, float y,
                                       std::uint32_t selected, bool turning) {
    if (selected >= scene.instances.size() || width == 0 || height == 0) return std::nullopt;
    const Pick pick = pickPixel(arrays, camera, width, height, x, y);
    if (pick.instance != selected) return std::nullopt;
    const Instance& instance = scene.instances[selected];
    std::optional<ObjectDrag> drag = startObjectDrag(selected, instance.transform, camera, width, height, x, y, pick.depth);
    if (drag && turning) {
        drag->turning = true;
        drag->turnedAtX = x;
        drag->centreLocal = prototypeCentre(scene, instance.prototype);
    }
    return drag;
}

namespace {

bool turnGrabbed(ObjectDrag& drag, Scene& scene, std::uint32_t width, float x) {
    const float dx = x - drag.turnedAtX;
    if (dx == 0) return false;
    drag.turnedAtX = x;
    const InstanceTurn turn = turnAboutCentre(scene.instances[drag.instance].transform, drag.centreLocal,
                                              dragTurnDegrees(dx, width));
    moveInstance(scene, drag.instance, turn.offset, turn.yawDegrees);
    return true;
}

}  // namespace

bool followCursor(ObjectDrag& drag, Scene& scene, const Camera& camera, std::uint32_t width, std::uint32_t height,
                  float x, float y) {
    if (drag.instance >= scene.instances.size() || width == 0 || height == 0) return false;
    if (drag.turning) return turnGrabbed(drag, scene, width, x);
    const Vec3 grabbed = scene.instances[drag.instance].transform.point(drag.grabbedLocal);
    const Vec3 offset = dragOffset(camera, width, height, grabbed, x, y);
    // Rounding leaves a still cursor a tiny offset: below a hundredth of a pixel, nothing moved
    // (a move would restart a paused viewer's accumulation every frame).
    if (!(length(offset) > 1e-5f * length(grabbed - camera.position))) return false;
    moveInstance(scene, drag.instance, offset, 0.0f);
    return true;
}

}  // namespace penumbra::viewer
