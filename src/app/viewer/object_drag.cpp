#include "app/viewer/object_drag.h"

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

}  // namespace penumbra::viewer
