#include "app/viewer/object_drag.h"

#include "core/aabb.h"
#include "render/scene_objects.h"

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

}  // namespace penumbra::viewer
